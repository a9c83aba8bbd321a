#!/usr/bin/env bash
# hil.docs_commands: every tools/vcan-vm command docs/testing.md shows is one a HIL test runs
# (as printed by run_hil.sh --print with the build dir "build"), and the main ones are shown.
set -euo pipefail
cd "$(dirname "$0")/../.."
doc=docs/testing.md
[[ -f $doc ]] || { echo "check_docs: $doc missing" >&2; exit 1; }

declare -A run_by_test=()
for case in prepare smoke failure_propagates script_timeout host_mode plant_sim daemon_motion daemon_faults daemon_link_down daemon_hang daemon_three_joints; do
  run_by_test[$(tests/hil/run_hil.sh --print "$case" build)]=$case
done

status=0
shown=0
while IFS= read -r line; do
  line=${line#"${line%%[![:space:]]*}"}
  shown=$((shown + 1))
  if [[ -z ${run_by_test[$line]:-} ]]; then
    echo "check_docs: $doc shows a command no HIL test runs: $line" >&2
    status=1
  fi
done < <(grep -E '^[[:space:]]*tools/vcan-vm ' "$doc")

for case in prepare smoke failure_propagates script_timeout plant_sim daemon_motion daemon_faults daemon_link_down daemon_hang; do
  cmd=$(tests/hil/run_hil.sh --print "$case" build)
  grep -qxF "$cmd" < <(sed 's/^[[:space:]]*//' "$doc") || { echo "check_docs: $doc does not show: $cmd" >&2; status=1; }
done
((status == 0)) && echo "check_docs: all $shown tools/vcan-vm commands in $doc are run by HIL tests"
exit "$status"
