#!/usr/bin/env bash
# system.configuration_docs: runs the commands of docs/configuration.md's "Previewing a
# description" section exactly as written, from a scratch folder that sees the build as "build"
# and the configs as "config", and checks that each wrote a PNG.
# Usage: configuration_docs.sh BUILD_DIR
set -euo pipefail
source "$(dirname "$0")/lib.sh"
system_setup "$1"
docs_scratch
mapfile -t commands < <(sed -n '/^## Previewing a description$/,/^## /s/^    \(build\/.*\)$/\1/p' "$src/docs/configuration.md")
[[ ${#commands[@]} -ge 3 ]] || fail "docs/configuration.md's preview section shows ${#commands[@]} commands, expected 3"
cd "$work"
for c in "${commands[@]}"; do
  run_shown "$c"
  png=$(sed -n 's/.*--out \([^ ]*\).*/\1/p' <<<"$c")
  [[ $(head -c 4 "$png" | od -An -c | tr -d ' ') == '211PNG' ]] || fail "$png is not a PNG"
done
echo "${#commands[@]} passed, 0 failed"
