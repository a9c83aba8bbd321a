#!/usr/bin/env bash
# cyber-plot: a cyber-plan CSV and an LCM log with ARM_TRAJECTORY become PNGs; bad input is exit 2.
# Usage: cyber_plot_cli_test.sh cyber-plot cyber-plan write_trajectory_log
set -u
plot=$1 plan=$2 writer=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
passes=0 failures=0
is_png() { [ "$(head -c 8 "$1" 2>/dev/null | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ]; }
expect() {  # expect NAME WANT_EXIT CMD...
  local name=$1 want=$2; shift 2
  "$@" >"$tmp/out" 2>"$tmp/err"; local got=$?
  if [ "$got" -eq "$want" ]; then passes=$((passes + 1)); echo "ok   $name"
  else failures=$((failures + 1)); echo "FAIL $name: exit $got, want $want: $(cat "$tmp/err")"; fi
}
"$plan" --from 0.20,1.57 --to 1.27,5.79 --coral --csv "$tmp/move.csv" >/dev/null || { echo "FAIL cyber-plan"; exit 1; }
expect "csv to png" 0 "$plot" --csv "$tmp/move.csv" --coral --out "$tmp/csv.png"
is_png "$tmp/csv.png" || { failures=$((failures + 1)); echo "FAIL csv.png is not a PNG"; }
"$writer" "$tmp/traj.lcmlog" || { echo "FAIL writing the log"; exit 1; }
expect "lcm log to png" 0 "$plot" --lcm-log "$tmp/traj.lcmlog" --out "$tmp/log.png"
is_png "$tmp/log.png" || { failures=$((failures + 1)); echo "FAIL log.png is not a PNG"; }
expect "request id filter" 0 "$plot" --lcm-log "$tmp/traj.lcmlog" --request-id 42 --out "$tmp/log42.png"
expect "no such request" 2 "$plot" --lcm-log "$tmp/traj.lcmlog" --request-id 7 --out "$tmp/x.png"
grep -q "undecodable" "$tmp/err" || { failures=$((failures + 1)); echo "FAIL garbage event not reported: $(cat "$tmp/err")"; }
expect "wrong channel" 2 "$plot" --lcm-log "$tmp/traj.lcmlog" --channel OTHER --out "$tmp/x.png"
printf 't,x\n1,2\n' >"$tmp/bad.csv"
expect "csv without the columns" 2 "$plot" --csv "$tmp/bad.csv" --out "$tmp/x.png"
expect "missing file" 2 "$plot" --csv "$tmp/none.csv" --out "$tmp/x.png"
expect "both sources" 2 "$plot" --csv "$tmp/move.csv" --lcm-log "$tmp/traj.lcmlog" --out "$tmp/x.png"
expect "no output" 2 "$plot" --csv "$tmp/move.csv"
echo "$passes passed, $failures failed"
[ "$failures" -eq 0 ]
