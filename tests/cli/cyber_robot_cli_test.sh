#!/usr/bin/env bash
# cyber-robot check: each shipped robot, and the three-joint and one-joint ones, passes (exit 0)
# with its report and pictures; a pose that collides in the default scene or a drive too weak for
# its load (a pivot, a wrist) fails (exit 1) naming it; bad usage is exit 2.
# Usage: cyber_robot_cli_test.sh cyber-robot
set -u
robot=$1
src=$(cd "$(dirname "$0")/../.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
passes=0 failures=0
expect() {  # expect NAME WANT_EXIT CMD...
  local name=$1 want=$2; shift 2
  "$@" >"$tmp/out" 2>"$tmp/err"; local got=$?
  if [ "$got" -eq "$want" ]; then passes=$((passes + 1)); echo "ok   $name"
  else failures=$((failures + 1)); echo "FAIL $name: exit $got, want $want: $(cat "$tmp/err")"; fi
}
says() {  # says NAME TEXT: the last command's output has TEXT
  if grep -qF -- "$2" "$tmp/out" "$tmp/err"; then passes=$((passes + 1)); echo "ok   $1"
  else failures=$((failures + 1)); echo "FAIL $1: no '$2' in: $(cat "$tmp/out" "$tmp/err")"; fi
}
for config in reefscape-2025 chargedup-2023-double-jointed reefscape-2025-elevator-pivot-wrist intake-pivot pivot-telescope; do
  expect "$config passes" 0 "$robot" check "$src/config/$config.toml" --png "$tmp/$config.png"
  says "$config reports its poses" "Named poses:"
  says "$config reports its moves" "ordered pairs plan"
  says "$config reports its drives" "Drives with the heaviest held set"
  says "$config reports its settings" "Planner settings"
  says "$config has no error" "0 errors"
  [ "$(head -c 4 "$tmp/$config.png" | od -An -c | tr -d ' ')" = "211PNG" ] && passes=$((passes + 1)) ||
    { failures=$((failures + 1)); echo "FAIL $config.png is not a PNG"; }
done
says "a picture per pose set" "pivot-telescope-ball.png"
expect "the minimal robot passes" 0 "$robot" check "$src/tests/fixtures/minimal-robot.toml"
says "the minimal robot's derived grid step" "planner.grid.step = [0.04, 0.08] (derived)"
sed 's/^\[poses.none\]$/[poses.none]\nINTO_STEP = [0.0, 0.9]/' "$src/config/pivot-telescope.toml" >"$tmp/collides.toml"
expect "a pose colliding in the default scene" 1 "$robot" check "$tmp/collides.toml"
says "the colliding pose is named" "error: pose [poses.none] INTO_STEP"
sed 's/^current_limit_amps = 60.0/current_limit_amps = 2.0/' "$src/config/pivot-telescope.toml" >"$tmp/weak.toml"
expect "a drive that cannot hold its load" 1 "$robot" check "$tmp/weak.toml"
says "the weak drive is named" "error: drive pivot cannot hold its load"
# Without its poses: planning their moves with a wrist this weak takes minutes.
sed 's/^current_limit_amps = 50.0/current_limit_amps = 1.0/; /^\[poses/,$d' "$src/config/reefscape-2025-elevator-pivot-wrist.toml" >"$tmp/weak-wrist.toml"
expect "a wrist that cannot hold its load" 1 "$robot" check "$tmp/weak-wrist.toml"
says "the weak wrist is named with its pose's three values" "error: drive wrist cannot hold its load or move both ways at ("
grep -qE "error: drive wrist .* at \([-0-9.]+, [-0-9.]+, [-0-9.]+\)" "$tmp/out" && passes=$((passes + 1)) ||
  { failures=$((failures + 1)); echo "FAIL the weak wrist's pose has not three values: $(cat "$tmp/out")"; }
printf 'name = "x"\n' >"$tmp/broken.toml"
expect "a description that does not load" 1 "$robot" check "$tmp/broken.toml"
expect "no command" 2 "$robot"
expect "unknown command" 2 "$robot" verify "$src/config/pivot-telescope.toml"
expect "help" 0 "$robot" --help
echo "$passes passed, $failures failed"
[ "$failures" -eq 0 ]
