#!/usr/bin/env bash
# system.lcm_spy: tools/lcm-spy, as docs/operations.md shows it, starts Debian's lcm-spy under
# Xvfb in a private network namespace while lcm_traffic publishes the six project types; a Java
# agent (spy_probe.jar, via JAVA_TOOL_OPTIONS) reads lcm-spy's channel table from inside its JVM.
# Passes when every channel shows up decoded as its type with messages counted and none
# undecodable. The table and a screenshot land in BUILD_DIR/system/lcm_spy/.
#   lcm_spy.sh BUILD_DIR
#   lcm_spy.sh --print-doc-commands    the commands docs/operations.md must show
set -euo pipefail
source "$(dirname "$0")/lib.sh"

spy='tools/lcm-spy'
spy_aside='tools/lcm-spy --lcm-url '"'"'udpm://239.255.76.67:7668?ttl=0'"'"
if [[ ${1:-} == --print-doc-commands ]]; then
  printf '%s\n' "$spy" "$spy_aside"
  exit 0
fi
[[ $# -eq 1 ]] || { echo "usage: $0 BUILD_DIR | --print-doc-commands" >&2; exit 2; }
system_setup "$1"
enter_netns "$src/tests/system/lcm_spy.sh" "$@"

unset LCM_DEFAULT_URL
work=$build_abs/system/lcm_spy
rm -rf "$work"
mkdir -p "$work"
export CYBER_LCMTYPES_JAR=$build_abs/lcmtypes/cyber_lcmtypes.jar
probe=$build_abs/tests/system/spy_probe.jar
[[ -f $CYBER_LCMTYPES_JAR && -f $probe ]] || fail "missing $CYBER_LCMTYPES_JAR or $probe (build them first)"

# The launcher refuses clearly when the types jar is missing.
if out=$(tools/lcm-spy --jar "$work/missing.jar" 2>&1); then fail "tools/lcm-spy started without a types jar"; fi
grep -q 'cyber_lcmtypes.jar not found' <<<"$out" || fail "unclear message for a missing jar: $out"

types=$(find "$src/lcmtypes" -maxdepth 1 -name '*.lcm' | wc -l)
expect=ARM_GOAL:arm_goal_t,ARM_STATE:arm_state_t,ARM_PLAN_STATUS:arm_plan_status_t
expect+=,ARM_TRAJECTORY:arm_trajectory_t,ARM_SETPOINT:arm_setpoint_t,ARM_DAEMON_STATUS:arm_daemon_status_t

# spy_check NAME COMMAND URL: runs COMMAND (a tools/lcm-spy line) under Xvfb while lcm_traffic
# publishes on URL, and checks the channel table the probe wrote into $work/NAME/.
spy_check() {
  local name=$1 command=$2 url=$3 dir=$work/$1 status=0 publisher header pair channel type row
  mkdir -p "$dir"
  "$build_abs/tests/system/lcm_traffic" publish --lcm-url "$url" --rate-hz 5 --duration-s 120 >"$dir/publisher.out" &
  publisher=$!
  echo "+ $command"
  JAVA_TOOL_OPTIONS="-javaagent:$probe=out=$dir/table.tsv;expect=$expect;min=3;timeout=90;screenshot=$dir/lcm-spy.png" \
    xvfb-run --auto-servernum --server-args='-screen 0 1024x768x24' \
    bash -c "$command" >"$dir/lcm-spy.out" 2>&1 || status=$?
  kill "$publisher" 2>/dev/null || true
  wait "$publisher" 2>/dev/null || true
  cat "$dir/lcm-spy.out"
  echo "--- lcm-spy channel table ($name)"
  cat "$dir/table.tsv" 2>/dev/null || true
  [[ $status -eq 0 ]] || fail "$name: lcm-spy did not show all six channels decoded (probe exit status $status)"

  # lcm-spy's own report: it found every project type (lcmtypes/*.lcm) on the class path.
  grep -qx "Found $types LCM types" "$dir/lcm-spy.out" || fail "$name: lcm-spy did not report 'Found $types LCM types'"
  # The table itself: a row per channel, the right type, messages counted, none undecodable.
  header=$(head -n1 "$dir/table.tsv")
  [[ $header == $'Channel\tType\tNum Msgs\tHz\t1/Hz\tJitter\tBandwidth\tUndecodable' ]] ||
    fail "$name: unexpected lcm-spy table header: $header"
  for pair in ${expect//,/ }; do
    channel=${pair%%:*} type=${pair#*:}
    row=$(awk -F'\t' -v c="$channel" '$1 == c' "$dir/table.tsv")
    [[ -n $row ]] || fail "$name: $channel missing from the lcm-spy table"
    IFS=$'\t' read -r _ shown_type count _ _ _ _ undecodable <<<"$row"
    [[ $shown_type == "$type" ]] || fail "$name: $channel shown as '$shown_type', expected $type"
    ((count >= 3)) || fail "$name: $channel: only $count messages"
    [[ $undecodable == 0 ]] || fail "$name: $channel: $undecodable undecodable messages"
  done
  [[ -s $dir/lcm-spy.png ]] || fail "$name: no screenshot"
  echo "lcm_spy: $name: all six channels decoded by lcm-spy (table and screenshot in $dir)"
}

spy_check default "$spy" 'udpm://239.255.76.67:5810?ttl=0'  # the daemon's default URL (docs/lcm.md)
spy_check aside "$spy_aside" 'udpm://239.255.76.67:7668?ttl=0'
