#!/usr/bin/env bash
# system.demo: runs tools/demo exactly as README.md shows it (and every other tools/demo command
# the docs show), from the source root with BUILD_DIR
# set to this build (tools/setup, cmake and ninja then have nothing to do), and checks what it
# printed and wrote: every goal's expected status, a PNG per planned goal, a capture that decodes
# strictly. Then checks, without the VM, that the demo's verdict can fail: the report on doctored
# copies of the results, and the refusal of an --out directory it did not write.
# Usage: demo.sh BUILD_DIR
set -euo pipefail
source "$(dirname "$0")/lib.sh"
system_setup "$1"

# The one tools/demo command README.md shows, run first; then every other tools/demo command the
# docs show (e.g. tools/demo --config FILE), each run and checked alike.
mapfile -t shown < <(sed -n 's/^    \(tools\/demo\>.*\)$/\1/p' README.md)
[[ ${#shown[@]} -eq 1 ]] || fail "README.md shows ${#shown[@]} tools/demo commands, expected one"
commands=("${shown[0]}")
while IFS= read -r line; do
  [[ " ${commands[*]} " == *" $line "* ]] || commands+=("$line")
done < <(grep -hE '^( {4}|\$ )?tools/demo\>' README.md docs/*.md | sed -E 's/^( {4}|\$ )//')
for command in "${commands[@]}"; do
  [[ $command =~ ^tools/demo(\ --config\ [^ ]+)?$ ]] ||
    fail "the docs show '$command'; this test runs only tools/demo [--config FILE]"
done

# tools/demo configures the build as tools/test does; a build tree configured otherwise would be
# reconfigured and rebuilt under the running tests, so it is then run without setup and build.
cache=$build_abs/CMakeCache.txt
setup_flag=""
if ! grep -qx 'CMAKE_BUILD_TYPE:STRING=RelWithDebInfo' "$cache" || ! grep -qx 'CMAKE_GENERATOR:INTERNAL=Ninja' "$cache"; then
  setup_flag=" --no-setup"
  echo "note: $build is not a RelWithDebInfo Ninja build: running the commands with --no-setup"
fi
out=$build_abs/demo
log=$build_abs/demo.log

# Runs tools/demo command $1 and checks what it printed and wrote.
run_demo() {
  local run=$1$setup_flag status=0 started=$SECONDS
  echo "+ BUILD_DIR=$build $run"
  BUILD_DIR=$build eval "$run" >"$log" 2>&1 || status=$?
  cat "$log"
  echo "note: '$run' took $((SECONDS - started)) s"
  [[ $status -eq 0 ]] || fail "$run exited with status $status"

  # Every goal's row shows its expected status; the verdict line is there.
  local ngoals=0 id label _target _pieces expected png
  while IFS='|' read -r id label _target _pieces expected; do
    ngoals=$((ngoals + 1))
    grep -qE "^$id\. .{0,60} $expected " "$log" || fail "$run: no row for goal $id ($label) ending $expected"
    grep -qF "$id. $label" "$log" || fail "$run: goal $id's row does not name it '$label'"
    png=$out/goal-$id.png
    if [[ $expected == "done" ]]; then
      [[ $(head -c 8 "$png" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]] || fail "$png is not a PNG"
      [[ $(stat -c %s "$png") -gt 20000 ]] || fail "$png is too small to hold the plot"
      grep -q "goal-$id.png" "$log" || fail "$run: the output does not name $png"
    else
      [[ ! -e $png ]] || fail "$run: goal $id expected $expected, yet it has a plot"
    fi
  done <"$out/goals.txt"
  ((ngoals >= 6)) || fail "$run: only $ngoals goals"
  # The README's demo shows a refusal; a tour of another robot's poses may have none to show.
  if [[ $1 == "${commands[0]}" ]]; then
    grep -Eq '^[0-9]+\. .* (failed|rejected) ' "$log" || fail "$run: no goal is refused in the demo"
  fi
  grep -qx "demo: all $ngoals goals ended as expected" "$log" || fail "$run: no verdict line for $ngoals goals"

  # The capture decodes strictly and holds the setpoints of both joints, named by the config the
  # run used (robot.toml); the LCM log is there.
  local decode=$build_abs/tools/cyber-can-decode/cyber-can-decode joint n
  "$decode" --config "$out/robot.toml" --strict "$out/bus.log" >"$out/check.decoded" 2>"$out/check.decode.err" ||
    fail "cyber-can-decode --strict $out/bus.log: $(cat "$out/check.decode.err")"
  for joint in $(python3 -c 'import sys, tomllib
print(" ".join(j["name"] for j in tomllib.load(open(sys.argv[1], "rb"))["joints"]))' "$out/robot.toml"); do
    n=$(grep -c " setpoint $joint " "$out/check.decoded" || true)
    ((n > 200)) || fail "$run: only $n $joint setpoints in bus.log"
  done
  [[ $(head -c 4 "$out/lcm.log" | od -An -tx1 | tr -d ' \n') == eda1da01 ]] || fail "$out/lcm.log is not an LCM log"
  rm -f "$out/check.decoded" "$out/check.decode.err"

  # demo.wpilog holds every entry of the session with the values of lcm.log's messages (the
  # test's entry names are the reference robot's); it reads back whatever the robot.
  if cmp -s "$out/robot.toml" config/reefscape-2025.toml; then
    CYBER_LCM_LOG=$out/lcm.log "$build_abs/tests/unit/wpilog/lcm_to_wpilog_test" >"$out/check.wpilog" 2>&1 ||
      { cat "$out/check.wpilog"; fail "the WPILOG of $out/lcm.log differs from its messages"; }
  fi
  "$build_abs/tools/cyber-wpilog/cyber-wpilog" --list "$out/demo.wpilog" >"$out/check.wpilog" ||
    fail "$out/demo.wpilog does not read back"
  rm -f "$out/check.wpilog"
}

run_demo "${commands[0]}"

# The verdict can fail: doctored copies of the results make tools/demo-report exit 1 naming why.
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
doctored() {
  rm -rf "$scratch/out"
  cp -r "$out" "$scratch/out"
}
expect_fail() {
  local why=$1 got=0
  tools/demo-report "$scratch/out" >"$scratch/report" 2>&1 || got=$?
  [[ $got -eq 1 ]] || { cat "$scratch/report"; fail "demo-report exited $got, not 1, when $why"; }
  grep -q "^demo: FAIL: $2" "$scratch/report" || { cat "$scratch/report"; fail "no 'demo: FAIL: $2' when $why"; }
  echo "ok: the report fails when $why"
}
first_done=$(grep -m1 '|done$' "$out/goals.txt" | cut -d'|' -f1)
refused=$(grep -m1 -vE '\|done$' "$out/goals.txt" | cut -d'|' -f1)
doctored
sed -i "s/^$first_done|\(.*\)|done\$/$first_done|\1|failed/" "$scratch/out/goals.txt"
expect_fail "goal $first_done was expected to fail" "goal $first_done .*ended done, expected failed"
doctored
sed -i -E "s/^($refused\|.*)\|[a-z]+\$/\1|done/" "$scratch/out/goals.txt"
expect_fail "the refused goal $refused was expected done" "goal $refused .*expected done"
doctored
rm "$scratch/out/goal-$first_done.png"
expect_fail "a plot is missing" "goal $first_done .*no plot"
doctored
# Moves the simulated elevator 10 mm away from every position it logged.
awk -F, -v OFS=, 'NR > 1 { $3 += 0.01 } { print }' "$out/plant.csv" >"$scratch/out/plant.csv"
expect_fail "the mechanism did not reach its targets" "goal $first_done .*from where it should be"

tools/demo --help >"$scratch/help" || fail "tools/demo --help failed"
grep -q -- "--out DIR" "$scratch/help" || fail "tools/demo --help does not document --out"

# An --out directory tools/demo did not write is refused and left alone.
mkdir "$scratch/mine"
echo keep >"$scratch/mine/precious"
got=0
BUILD_DIR=$build tools/demo --no-setup --out "$scratch/mine" >"$scratch/refused" 2>&1 || got=$?
[[ $got -eq 2 && $(cat "$scratch/mine/precious") == keep ]] || fail "tools/demo --out on a foreign directory: exit $got"
grep -q "not written by tools/demo" "$scratch/refused" || fail "no reason given for refusing --out"
echo "ok: a foreign --out directory is refused and left alone"

for command in "${commands[@]:1}"; do
  run_demo "$command"
done
echo "1 passed, 0 failed"
