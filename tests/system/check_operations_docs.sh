#!/usr/bin/env bash
# system.operations_docs: the commands docs/operations.md shows in the sections this checks
# (install, systemd, CAN, lcm-spy, AdvantageScope, arm64, Systemcore) are exactly the commands the system tests run, as each test
# prints them with --print-doc-commands (build dir "build"): none shown that no test runs, none
# run that the page does not show. Other sections of the page are not checked here, but for the
# keys the Systemcore package changes in its configuration (tools/systemcore-ipk).
set -euo pipefail
cd "$(dirname "$0")/../.."
doc=docs/operations.md
[[ -f $doc ]] || { echo "check_operations_docs: $doc missing" >&2; exit 1; }
checked_sections=("## Install and package" "## Running under systemd" "## CAN interface with systemd-networkd"
                  "## lcm-spy, recording and replay" "## AdvantageScope" "## arm64 coprocessors"
                  "## Systemcore")

declare -A run_by_test=()
for script in system/package system/unit_files system/lcm_spy system/lcm_record_replay arm64/package_run \
              arm64/systemcore_bundle; do
  printed=$("tests/$script.sh" --print-doc-commands) ||
    { echo "check_operations_docs: $script.sh --print-doc-commands failed" >&2; exit 1; }
  while IFS= read -r command; do
    run_by_test[$command]=$script
  done <<<"$printed"
done

# The lines of the ```sh blocks inside the checked sections.
shown_commands() {
  local in_section=0 in_block=0 line heading
  while IFS= read -r line; do
    if [[ $line == '## '* ]]; then
      in_section=0
      for heading in "${checked_sections[@]}"; do [[ $line == "$heading" ]] && in_section=1; done
      continue
    fi
    if [[ $line == '```'* ]]; then
      if ((in_block)); then in_block=0; elif [[ $line == '```sh' ]]; then in_block=1; fi
      continue
    fi
    ((in_section && in_block)) && [[ -n $line ]] && echo "$line"
  done <"$doc"
  return 0
}

status=0
for heading in "${checked_sections[@]}"; do
  grep -qxF "$heading" "$doc" || { echo "check_operations_docs: no section '$heading'" >&2; status=1; }
done
declare -A shown=()
while IFS= read -r command; do
  shown[$command]=1
  if [[ -z ${run_by_test[$command]:-} ]]; then
    echo "check_operations_docs: $doc shows a command no system test runs: $command" >&2
    status=1
  fi
done < <(shown_commands)
for command in "${!run_by_test[@]}"; do
  if [[ -z ${shown[$command]:-} ]]; then
    echo "check_operations_docs: ${run_by_test[$command]}.sh runs a command $doc does not show: $command" >&2
    status=1
  fi
done

# The Systemcore configuration: the keys tools/systemcore-ipk sets are those the page's table lists,
# and the page counts them right (it once said three when the tool set four).
mapfile -t ipk_keys < <(sed -n 's/^set_key \([a-z_]*\) .*/\1/p' tools/systemcore-ipk)
numbers=(zero one two three four five six seven eight nine)
count=${#ipk_keys[@]}
for key in "${ipk_keys[@]}"; do
  grep -q "^| \`$key\` |" "$doc" || { echo "check_operations_docs: $doc does not list the key $key tools/systemcore-ipk sets" >&2; status=1; }
done
for phrase in "with ${numbers[$count]} keys" "exactly those ${numbers[$count]} lines changed"; do
  tr '\n' ' ' <"$doc" | grep -qF "$phrase" ||
    { echo "check_operations_docs: $doc does not say '$phrase' (tools/systemcore-ipk sets $count keys)" >&2; status=1; }
done

((status == 0)) && echo "check_operations_docs: all ${#shown[@]} commands in $doc are run by system tests;" \
  "the Systemcore configuration's $count keys are listed"
exit "$status"
