#!/usr/bin/env bash
# cyber-plan's command-line contract (design.md): outputs, exit codes and one-line reasons.
# Usage: cyber_plan_cli_test.sh PATH/TO/cyber-plan CONFIG.toml
set -u
plan=$1
config=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
passes=0
check() {  # check NAME EXPECTED_EXIT ARGS... ; stderr must then be one line
  local name=$1 want=$2
  shift 2
  "$plan" "$@" >"$tmp/out" 2>"$tmp/err"
  local got=$?
  if [ "$got" -ne "$want" ]; then
    echo "FAIL $name: exit $got, want $want; stderr: $(cat "$tmp/err")"
    failures=$((failures + 1))
  elif [ "$want" -ne 0 ] && [ "$(wc -l <"$tmp/err")" -ne 1 ]; then
    echo "FAIL $name: want exactly one line on stderr, got: $(cat "$tmp/err")"
    failures=$((failures + 1))
  else
    echo "ok   $name: exit $got $(head -c 160 "$tmp/err")"
    passes=$((passes + 1))
  fi
}
expect_in() {  # expect_in NAME FILE TEXT
  if ! grep -qF -- "$3" "$2"; then
    echo "FAIL $1: '$3' not in $2: $(head -c 300 "$2")"
    failures=$((failures + 1))
  fi
}

check "plans a public move" 0 --config "$config" --from 0.20,1.57 --to 1.97,5.17 --csv "$tmp/t.csv" --json
expect_in "json keys" "$tmp/out" '"duration_s":'
for key in grid_ms search_ms smooth_ms topp_ms total_ms primal_residual dual_residual min_clearance_m method; do
  expect_in "json $key" "$tmp/out" "\"$key\":"
done
header='t,elevator_pos,elevator_vel,elevator_acc,elevator_volts,elevator_amps,arm_pos,arm_vel,arm_acc,arm_volts,arm_amps'
if [ "$(head -n 1 "$tmp/t.csv")" != "$header" ]; then
  echo "FAIL csv header: $(head -n 1 "$tmp/t.csv")"; failures=$((failures + 1))
fi
# 1 ms rows from t = 0 to the duration; the last row is the goal.
python3 - "$tmp/t.csv" "$tmp/out" <<'PY' || failures=$((failures + 1))
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1])))
summary = json.loads(open(sys.argv[2]).read())
t = [float(r['t']) for r in rows]
gaps = [b - a for a, b in zip(t, t[1:])]
assert t[0] == 0.0 and max(gaps) <= 0.0010001 and min(gaps) > 0, 'rows are not 1 ms apart'
assert abs(t[-1] - summary['duration_s']) < 1e-6, (t[-1], summary['duration_s'])
assert abs(float(rows[-1]['elevator_pos']) - 1.97) < 1e-4 and abs(float(rows[-1]['arm_pos']) - 5.17) < 1e-4
assert summary['min_clearance_m'] >= 0.03 - 1e-9, summary
print('ok   csv: %d rows, %.3f s' % (len(rows), t[-1]))
PY
# --csv-step: a seeded random moving start of the double-jointed arm whose acceleration column,
# integrated across 1 ms samples, misses its velocity by 4.5 % of the elbow's peak speed (the
# jumps of the final braking fall between samples); at 0.1 ms the same trajectory's columns agree
# (docs/moving-starts.md, "Consistent columns").
check "csv step" 0 --config "$(dirname "$config")/chargedup-2023-double-jointed.toml" --pieces cube \
  --from=1.31571509,3.89117865 --to=1.91358023,3.72908321 --from-velocity=2.26365245,-0.579524693 \
  --csv "$tmp/fine.csv" --csv-step 0.0001
python3 - "$tmp/fine.csv" <<'PY' || failures=$((failures + 1))
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
t = [float(r['t']) for r in rows]
gaps = [b - a for a, b in zip(t, t[1:])]
assert max(gaps) <= 0.0001 + 1e-9 and min(gaps) > 0, 'rows are not 0.1 ms apart'
def acceleration_error(rows, step):
    worst = 0.0
    for joint in ('shoulder', 'elbow'):
        v = [float(r[joint + '_vel']) for r in rows[::step]]
        a = [float(r[joint + '_acc']) for r in rows[::step]]
        tt = t[::step]
        peak, integral = max(abs(x) for x in v), 0.0
        for i in range(1, len(v)):
            integral += 0.5 * (tt[i] - tt[i - 1]) * (a[i] + a[i - 1])
            worst = max(worst, abs(v[i] - v[0] - integral) / peak)
    return worst
fine, coarse = acceleration_error(rows, 1), acceleration_error(rows, 10)
assert fine <= 0.02 < coarse, (fine, coarse)
print('ok   csv step: %d rows; acceleration column off by %.2f %% at 0.1 ms, %.2f %% at 1 ms' % (len(rows), 100 * fine, 100 * coarse))
PY
# Without --csv-step, the same move's CSV is written at the widest spacing at which its columns
# agree, and stderr says so.
check "csv step chosen" 0 --config "$(dirname "$config")/chargedup-2023-double-jointed.toml" --pieces cube \
  --from=1.31571509,3.89117865 --to=1.91358023,3.72908321 --from-velocity=2.26365245,-0.579524693 \
  --csv "$tmp/chosen.csv"
expect_in "csv step chosen named" "$tmp/err" "the CSV's samples are 0.25 ms apart"
python3 - "$tmp/chosen.csv" <<'PY' || failures=$((failures + 1))
import csv, sys
t = [float(r['t']) for r in csv.DictReader(open(sys.argv[1]))]
gaps = [b - a for a, b in zip(t, t[1:])]
assert max(gaps) <= 0.00025 + 1e-9 and max(gaps[:-1]) > 0.00025 - 1e-9, 'rows are not 0.25 ms apart'
print('ok   csv step chosen: %d rows 0.25 ms apart' % len(t))
PY
# A moving start of the reference robot whose path turns (a joint reverses): on 1 ms samples a ride
# along them passes the turn faster than the motors can, more than 1 % faster than the plan, so
# the CSV is written finer, as stderr says; the chosen spacing is at most 0.1 ms (docs/moving-starts.md,
# "The CSV's spacing").
check "csv step for a turn" 0 --config "$config" --pieces coral --scene-offset 0.2 \
  --from=1.60381554,2.49688491 --to=0.926369007,4.33561299 --from-velocity=-3.1092032,7.55192558 \
  --csv "$tmp/turn.csv"
expect_in "csv step for a turn named" "$tmp/err" "a ride along its samples would be more than 1 % faster"
python3 - "$tmp/turn.csv" "$tmp/err" <<'PY' || failures=$((failures + 1))
import csv, re, sys
step = float(re.search(r"samples are ([0-9.]+) ms apart", open(sys.argv[2]).read()).group(1)) / 1e3
t = [float(r['t']) for r in csv.DictReader(open(sys.argv[1]))]
gaps = [b - a for a, b in zip(t, t[1:])]
assert step <= 0.0001 and max(gaps) <= step + 1e-9 and max(gaps[:-1]) > step - 1e-9, (step, max(gaps))
print('ok   csv step for a turn: %d rows %g ms apart' % (len(t), step * 1e3))
PY
check "csv step out of range" 2 --config "$config" --from 0.20,1.57 --to 1.97,5.17 --csv "$tmp/t.csv" --csv-step 0.002
check "plot" 0 --config "$config" --from STOW --to L3 --pieces coral --plot "$tmp/p.png"  # README's picture
if [ "$(head -c 8 "$tmp/p.png" | od -An -tx1 | tr -d ' ')" != "89504e470d0a1a0a" ]; then
  echo "FAIL plot: not a PNG"; failures=$((failures + 1))
fi
check "embedded default config" 0 --from 0.58,2.97 --to 1.93,1.71 --pieces algae
check "moving start" 0 --config "$config" --from 0.8,1.57 --to 1.5,1.57 --from-velocity 0.5,0.0
check "joined values" 0 --config="$config" --from=0.8,1.57 --to=1.5,1.57 --from-velocity=-0.2,1
check "zero-length move" 0 --config "$config" --from 0.2,1.57 --to 0.2,1.57
check "help" 0 --help

check "NaN start" 2 --config "$config" --from nan,1.57 --to 1.97,5.17
check "inf goal" 2 --config "$config" --from 0.2,1.57 --to 1.97,inf
check "malformed pair" 2 --config "$config" --from 0.2 --to 1.97,5.17
check "missing --to" 2 --config "$config" --from 0.2,1.57
check "unknown argument" 2 --config "$config" --from 0.2,1.57 --to 1.97,5.17 --fast
check "unknown piece" 2 --config "$config" --from 0.2,1.57 --to 1.97,5.17 --pieces cone
check "scene offset out of range" 2 --config "$config" --from 0.2,1.57 --to 1.97,5.17 --scene-offset 0.5
check "scene offset in range" 0 --config "$config" --from 0.2,1.57 --to 1.97,5.17 --scene-offset 0.1
check "another robot" 0 --config "$(dirname "$config")/chargedup-2023-double-jointed.toml" --from 1.5708,3.1416 --to 1.3257,3.929
# Named poses: --from/--to NAME is a pose of the held set's [poses.SET] table in the config
# (config/reefscape-2025.toml: coral L3 = [1.27, 5.79], none L3 = [1.22, 5.69]).
check "named poses" 0 --config "$config" --from STOW --to L3 --pieces coral
expect_in "named poses resolved" "$tmp/out" "planned STOW (0.200 m, 1.570 rad) -> L3 (1.270 m, 5.790 rad)"
check "named pose of none" 0 --config "$config" --from STOW --to L3
expect_in "named pose of none resolved" "$tmp/out" "-> L3 (1.220 m, 5.690 rad)"
check "name and numbers" 0 --config "$config" --from=0.20,1.57 --to=L3 --pieces coral --json
expect_in "name and numbers json" "$tmp/out" '"duration_s":'
check "numbers and name" 0 --config "$config" --from 1.27,5.79 --to STOW --pieces coral
expect_in "numbers and name resolved" "$tmp/out" "planned (1.270 m, 5.790 rad) -> STOW (0.200 m, 1.570 rad)"
check "unknown pose name" 2 --config "$config" --from STOW --to L5 --pieces coral
expect_in "unknown pose name lists the set's" "$tmp/err" \
  '--to: no pose "L5" for the held set "coral" (its poses: STOW, INTAKE, L1, L2, L3, L4, NET)'
check "pose name of another held set" 2 --config "$config" --from HOLD_HIGH --to STOW --pieces coral
expect_in "another set's pose named" "$tmp/err" \
  '--from: no pose "HOLD_HIGH" for the held set "coral" (its poses: STOW, INTAKE, L1, L2, L3, L4, NET); it is a pose of "algae"'
check "pose name and number" 2 --config "$config" --from STOW,1 --to L3
check "wrong number of values" 2 --config "$config" --from 0.2,1.57,0 --to L3
expect_in "wrong number of values named" "$tmp/err" "--from: expects 2 values, one per joint (elevator, arm), got 3"

check "empty joined value" 2 --config= --from 0.2,1.57 --to 1.97,5.17
expect_in "empty value named" "$tmp/err" "--config needs a value"
check "missing config" 2 --config "$tmp/none.toml" --from 0.2,1.57 --to 1.97,5.17
printf 'name = "x"\n' >"$tmp/bad.toml"
check "invalid config" 2 --config "$tmp/bad.toml" --from 0.2,1.57 --to 1.97,5.17
check "unknown scene" 2 --config "$config" --from 0.2,1.57 --to 1.97,5.17 --scene nowhere
check "goal out of range" 3 --config "$config" --from 0.2,1.57 --to 2.5,1.57
check "start out of range" 3 --config "$config" --from 0.2,-1 --to 1.97,5.17
# Coral L4 of the public poses lies in a pocket no other coral pose reaches (issue 2 note).
check "unreachable goal" 3 --config "$config" --from 0.20,1.57 --to 1.98,5.39 --pieces coral
expect_in "no path reason" "$tmp/err" "no path"
check "goal in collision" 3 --config "$config" --from 0.2,1.57 --to 0.0,0.0
expect_in "collision reason" "$tmp/err" "collision"
check "unwritable csv" 2 --config "$config" --from 0.2,1.57 --to 1.97,5.17 --csv /nonexistent/dir/t.csv

# The minimal robot (tests/fixtures/minimal-robot.toml: no [planner], no [daemon]) loads with its
# derived settings and plans past its shelf (docs/configuration.md, "Defaults derived from the robot").
minimal="$(dirname "$config")/../tests/fixtures/minimal-robot.toml"
check "minimal robot" 0 --config "$minimal" --from 0.0,1.57 --to 1.0,0.0 --json
expect_in "minimal robot plans" "$tmp/out" '"status":"ok"'
echo "$passes passed, $failures failed"
[ "$failures" -eq 0 ]
