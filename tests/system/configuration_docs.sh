#!/usr/bin/env bash
# system.configuration_docs: runs the commands of docs/configuration.md's "Previewing a
# description" and "Checking a robot" sections exactly as written, from a scratch folder that sees
# the build as "build" and the configs as "config", and checks that each wrote a PNG.
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
# "Checking a robot": cyber-robot check as shown, which must pass on the reference robot and draw.
mapfile -t checks < <(sed -n '/^## Checking a robot$/,/^## /s/^    \(build\/.*\)$/\1/p' "$src/docs/configuration.md")
[[ ${#checks[@]} -ge 1 ]] || fail "docs/configuration.md's \"Checking a robot\" shows no command"
for c in "${checks[@]}"; do
  run_shown "$c"
  png=$(sed -n 's/.*--png \([^ ]*\).*/\1/p' <<<"$c")
  [[ $(head -c 4 "$png" | od -An -c | tr -d ' ') == '211PNG' ]] || fail "$png is not a PNG"
done
echo "$((${#commands[@]} + ${#checks[@]})) passed, 0 failed"
