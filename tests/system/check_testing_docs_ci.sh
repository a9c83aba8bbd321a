#!/usr/bin/env bash
# system.testing_docs_ci: the tools/fuzz, tools/soak and sanitizer commands docs/testing.md shows
# in its sh blocks are lines .ci/run runs (so the page shows what CI does), and there is one of each.
set -euo pipefail
cd "$(dirname "$0")/../.."
doc=docs/testing.md
status=0
shown=$(awk '/^```sh$/ { inside = 1; next } /^```$/ { inside = 0 } inside' "$doc" |
        sed 's/^[[:space:]]*//' | grep -E '^(tools/fuzz|tools/soak|CYBER_SANITIZE=)' || true)
for tool in tools/fuzz tools/soak CYBER_SANITIZE=; do
  grep -q "^$tool" <<<"$shown" || { echo "check_testing_docs_ci: $doc shows no $tool command" >&2; status=1; }
done
while IFS= read -r line; do
  [ -n "$line" ] || continue
  grep -qxF "$line" .ci/run || { echo "check_testing_docs_ci: .ci/run does not run: $line" >&2; status=1; }
done <<<"$shown"
((status == 0)) && echo "check_testing_docs_ci: $(wc -l <<<"$shown") commands of $doc are run by .ci/run"
exit "$status"
