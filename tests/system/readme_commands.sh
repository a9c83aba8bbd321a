#!/usr/bin/env bash
# Runs the commands README.md shows (besides tools/test, which .ci/run runs, and tools/demo, which
# system.demo runs) exactly as written, from a scratch folder that sees the build as "build", and
# checks what they write.
# Usage: readme_commands.sh BUILD_DIR
set -euo pipefail
source "$(dirname "$0")/lib.sh"
system_setup "$1"
docs_scratch
mapfile -t commands < <(sed -n 's/^    \(build\/.*\)$/\1/p' "$src/README.md")
[[ ${#commands[@]} -gt 0 ]] || fail "README.md shows no build/ commands"
grep -qx '    tools/test' "$src/README.md" && grep -qx '    tools/demo' "$src/README.md" || fail "README.md lost its quick start"
grep -q 'tools/test' "$src/.ci/run" || fail ".ci/run does not run tools/test"
cd "$work"
for c in "${commands[@]}"; do
  run_shown "$c"
done
[[ $(head -n 1 move.csv) == t,elevator_pos,* ]] || fail "move.csv has no header"
[[ $(head -c 4 move.png | od -An -c | tr -d ' ') == '211PNG' ]] || fail "move.png is not a PNG"
[[ $(head -c 4 move-world.png | od -An -c | tr -d ' ') == '211PNG' ]] || fail "move-world.png is not a PNG"
grep -q acTL move-world-anim.png || fail "move-world-anim.png is not an animated PNG"
echo "1 passed, 0 failed"
