#!/usr/bin/env bash
# cyber-plot: a cyber-plan CSV and an LCM log with ARM_TRAJECTORY become PNGs, the world view (a
# pose, a filmstrip and an APNG of a move) and the preview of a description too; bad input is
# exit 2.
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
"$plan" --from 0.20,1.57 --to 1.27,5.79 --pieces coral --csv "$tmp/move.csv" >/dev/null || { echo "FAIL cyber-plan"; exit 1; }
expect "csv to png" 0 "$plot" --csv "$tmp/move.csv" --pieces coral --out "$tmp/csv.png"
is_png "$tmp/csv.png" || { failures=$((failures + 1)); echo "FAIL csv.png is not a PNG"; }
"$writer" "$tmp/traj.lcmlog" || { echo "FAIL writing the log"; exit 1; }
expect "lcm log to png" 0 "$plot" --lcm-log "$tmp/traj.lcmlog" --out "$tmp/log.png"
is_png "$tmp/log.png" || { failures=$((failures + 1)); echo "FAIL log.png is not a PNG"; }
expect "request id filter" 0 "$plot" --lcm-log "$tmp/traj.lcmlog" --request-id 42 --out "$tmp/log42.png"
expect "no such request" 2 "$plot" --lcm-log "$tmp/traj.lcmlog" --request-id 7 --out "$tmp/x.png"
grep -q "undecodable" "$tmp/err" || { failures=$((failures + 1)); echo "FAIL garbage event not reported: $(cat "$tmp/err")"; }
expect "wrong channel" 2 "$plot" --lcm-log "$tmp/traj.lcmlog" --channel OTHER --out "$tmp/x.png"
expect "world at a pose" 0 "$plot" --world --at 1.22,5.69 --out "$tmp/pose.png"
is_png "$tmp/pose.png" || { failures=$((failures + 1)); echo "FAIL pose.png is not a PNG"; }
expect "world filmstrip and animation" 0 "$plot" --world --csv "$tmp/move.csv" --pieces coral --frames 4 --out "$tmp/film.png" --animation "$tmp/anim.png"
is_png "$tmp/film.png" && is_png "$tmp/anim.png" || { failures=$((failures + 1)); echo "FAIL film.png or anim.png is not a PNG"; }
grep -q acTL "$tmp/anim.png" || { failures=$((failures + 1)); echo "FAIL anim.png is not animated (no acTL)"; }
expect "world from the lcm log" 0 "$plot" --world --lcm-log "$tmp/traj.lcmlog" --out "$tmp/film-log.png"
src=$(cd "$(dirname "$0")/../.." && pwd)
expect "config preview" 0 "$plot" --config "$src/config/reefscape-2025.toml" --pieces coral --out "$tmp/preview.png"
is_png "$tmp/preview.png" || { failures=$((failures + 1)); echo "FAIL preview.png is not a PNG"; }
sed '/^\[poses/,/^\[daemon\]/{/^\[daemon\]/!d}' "$src/config/reefscape-2025.toml" >"$tmp/no-poses.toml"
expect "config preview without named poses" 0 "$plot" --config "$tmp/no-poses.toml" --out "$tmp/preview2.png"
sed 's/^L3 = \[1.22, 5.69\]/L3 = [3.0, 5.69]/' "$src/config/reefscape-2025.toml" >"$tmp/bad-pose.toml"
expect "config with a pose out of range" 2 "$plot" --config "$tmp/bad-pose.toml" --out "$tmp/x.png"
grep -q "poses.none.L3" "$tmp/err" || { failures=$((failures + 1)); echo "FAIL bad pose not named: $(cat "$tmp/err")"; }
sed 's/^\[poses.none\]$/[poses.none]\nINSIDE_REEF = [1.5, 6.05]/' "$src/config/reefscape-2025.toml" >"$tmp/colliding-pose.toml"
expect "config preview with a pose closer than the clearance" 0 "$plot" --config "$tmp/colliding-pose.toml" --out "$tmp/preview3.png"
grep -q "warning: pose \[poses.none\] INSIDE_REEF" "$tmp/err" || { failures=$((failures + 1)); echo "FAIL colliding pose not warned: $(cat "$tmp/err")"; }
expect "world pose out of range" 2 "$plot" --world --at 3.0,1.0 --out "$tmp/x.png"
expect "world pose malformed" 2 "$plot" --world --at 1.0 --out "$tmp/x.png"
expect "world without a source" 2 "$plot" --world --out "$tmp/x.png"
expect "world with two sources" 2 "$plot" --world --at 1,1 --csv "$tmp/move.csv" --out "$tmp/x.png"
expect "animation of a pose" 2 "$plot" --world --at 1,1 --animation "$tmp/a.png" --out "$tmp/x.png"
expect "animation without --world" 2 "$plot" --csv "$tmp/move.csv" --animation "$tmp/a.png" --out "$tmp/x.png"
expect "bad frame count" 2 "$plot" --world --csv "$tmp/move.csv" --frames 1 --out "$tmp/x.png"
expect "unknown scene" 2 "$plot" --world --at 1,1 --scene nowhere --out "$tmp/x.png"
# Chains of three joints and of one: a planned move's picture (slices at the wrist's start and goal
# values; the pivot's range over time), its filmstrip, a pose, the preview; a pose or a trajectory
# of another joint count is refused.
three="$src/config/reefscape-2025-elevator-pivot-wrist.toml" one="$src/config/intake-pivot.toml"
"$plan" --config "$three" --from STOW --to L3 --csv "$tmp/three.csv" >/dev/null || { echo "FAIL cyber-plan, three joints"; exit 1; }
"$plan" --config "$one" --from STOW --to DEPLOYED --csv "$tmp/one.csv" >/dev/null || { echo "FAIL cyber-plan, one joint"; exit 1; }
for n in three one; do
  config=$([ $n = three ] && echo "$three" || echo "$one")
  expect "$n joints: csv to png" 0 "$plot" --config "$config" --csv "$tmp/$n.csv" --out "$tmp/$n.png"
  expect "$n joints: filmstrip and animation" 0 "$plot" --world --config "$config" --csv "$tmp/$n.csv" --out "$tmp/$n-film.png" --animation "$tmp/$n-anim.png"
  expect "$n joints: preview" 0 "$plot" --config "$config" --out "$tmp/$n-preview.png"
  is_png "$tmp/$n.png" && is_png "$tmp/$n-film.png" && is_png "$tmp/$n-anim.png" && is_png "$tmp/$n-preview.png" ||
    { failures=$((failures + 1)); echo "FAIL a picture of $n joints is not a PNG"; }
done
expect "three joints: a pose" 0 "$plot" --world --config "$three" --at 0.6744,1.0353,-1.6461 --out "$tmp/three-at.png"
expect "one joint: a pose" 0 "$plot" --world --config "$one" --at 0.95 --out "$tmp/one-at.png"
expect "three joints: a pose of two values" 2 "$plot" --world --config "$three" --at 0.6,1.0 --out "$tmp/x.png"
grep -q "has 2 values, reefscape-2025-elevator-pivot-wrist has 3 joints" "$tmp/err" || { failures=$((failures + 1)); echo "FAIL the joint count not named: $(cat "$tmp/err")"; }
expect "three joints: a trajectory of two" 2 "$plot" --config "$three" --lcm-log "$tmp/traj.lcmlog" --out "$tmp/x.png"
grep -q "the trajectory has 2 joints, the robot description 3" "$tmp/err" || { failures=$((failures + 1)); echo "FAIL the joint counts not named: $(cat "$tmp/err")"; }
printf 't,x\n1,2\n' >"$tmp/bad.csv"
expect "csv without the columns" 2 "$plot" --csv "$tmp/bad.csv" --out "$tmp/x.png"
expect "missing file" 2 "$plot" --csv "$tmp/none.csv" --out "$tmp/x.png"
expect "both sources" 2 "$plot" --csv "$tmp/move.csv" --lcm-log "$tmp/traj.lcmlog" --out "$tmp/x.png"
expect "no output" 2 "$plot" --csv "$tmp/move.csv"
echo "$passes passed, $failures failed"
[ "$failures" -eq 0 ]
