#!/usr/bin/env bash
# Host side of the HIL tests (ctest label hil): runs tools/vcan-vm for one case from the source
# root, the same command docs/testing.md shows, and checks its exit status and what came out.
# Usage: tests/hil/run_hil.sh [--print] CASE BUILD_DIR
#   CASE: prepare | smoke | failure_propagates | script_timeout | host_mode | plant_sim |
#         daemon_motion | daemon_faults | daemon_link_down | daemon_hang | daemon_three_joints
#   --print: only print the tools/vcan-vm command of the case (for the docs check)
set -uo pipefail

print_only=0
[[ ${1:-} == --print ]] && print_only=1 && shift
[[ $# -eq 2 ]] || { echo "usage: $0 [--print] CASE BUILD_DIR" >&2; exit 2; }
src=$(cd "$(dirname "$0")/../.." && pwd)
build_abs=$(realpath -m "$2")
cd "$src" || exit 2
# Relative to the source root when inside it, so the commands read as in docs/testing.md.
build=$(realpath -m --relative-base="$src" "$build_abs")
export CYBER_VCAN_CACHE=$build/vcan-vm
probe=$build/tests/hil/vcan_probe
plant_sim=$build/tools/cyber-plant-sim/cyber-plant-sim
daemon_bins=(--bin "$build/daemon/app/cyber-plannerd" --bin "$build/tools/cyber-goal/cyber-goal" --bin "$plant_sim"
  --bin "$build/tools/cyber-can-decode/cyber-can-decode" --bin /usr/bin/lcm-logger --file tests/hil/hil_guest.sh)
out=$build/hil/$1
log=$build/hil/$1.log

# One VM run of a daemon case, boot included: its scripts take 15-70 s in the emulated guest; the
# limit allows for a guest several times slower than that (docs/testing.md).
daemon_timeout_s=300
# The daemon's start-up with the reference robot (its grids: 0.97 s natively) on top, scaled by
# tools/vcan-vm to the guest's measured speed (docs/testing.md, "Guest speed and start-up"): in the
# guest, beside the simulator, it has taken up to 3.6 times that; 8 s leaves it more than twice.
# Unused, it costs nothing: the watchdog gives the rest back once the daemon is ready.
daemon_start_s=8
# The three-joint robot's start-up, its grids read from the cache the host built natively
# (tests/hil/grid_cache.sh; the guest's daemon fails the run if it has to build one): about 1 s
# natively, as the reference robot's, so the same allowance.
three_joint_start_s=8
# The grid cache of the three-joint robot (shared with tools/demo --config of that robot).
three_joint_cache=$build/grid-cache/reefscape-2025-elevator-pivot-wrist
# The hang test's script limit once the daemon is ready (the watchdog gives back the rest of the
# allowance then): the script hangs right after.
hang_script_s=10

fail() { echo "run_hil: FAIL ($1): ${*:2}" >&2; exit 1; }

# What a daemon case left in DIR, printed when it failed or timed out, so the ctest output has it.
show_evidence() {
  local dir=$1 f
  echo "run_hil: evidence from $dir"
  [[ -s $dir/failure.txt ]] && echo "  failed: $(cat "$dir/failure.txt")"
  for f in script.log daemon.log plant_sim.err goal*.out cpu.txt; do
    [[ -s $dir/$f ]] || continue
    echo "  --- $f (last 40 lines)"
    tail -n 40 "$dir/$f" | sed 's/^/  | /'
  done
  if [[ -s $dir/timeout-tasks.txt ]]; then
    echo "  --- timeout-tasks.txt: every task when the time ran out (kernel stacks in the file)"
    grep -E '^(task|uptime|after)' "$dir/timeout-tasks.txt" | sed 's/^/  | /'
  fi
  if [[ -s $dir/bus.log ]]; then
    echo "  --- bus.log: $(wc -l <"$dir/bus.log") frames, the last 10"
    tail -n 10 "$dir/bus.log" | sed 's/^/  | /'
  fi
}

# The tools/vcan-vm arguments of each case, in the array args.
args_for() {
  case $1 in
    prepare) args=(--prepare) ;;
    smoke) args=(--auto --bin "$probe" --out "$out" --run tests/hil/vcan_smoke.sh) ;;
    failure_propagates) args=(--auto --out "$out" --run tests/hil/vcan_exit3.sh) ;;
    script_timeout) args=(--auto --timeout 90 --script-timeout 3 --out "$out" --run tests/hil/vcan_hang.sh) ;;
    host_mode)
      args=(--vm --bin /usr/bin/bash --bin /usr/bin/unshare --bin /usr/bin/timeout --bin /usr/bin/setpriv
        --bin "$probe" --file tools/vcan-vm --file tests/hil/vcan_smoke.sh --file tests/hil/vcan_exit3.sh
        --out "$out" --run tests/hil/vcan_host_mode.sh)
      ;;
    plant_sim)
      args=(--auto --bin "$plant_sim" --bin /usr/bin/lcm-logger --bin /usr/bin/chrt
        --file "$build/hil/plant_sim.setpoints.log:setpoints.log"
        --out "$out" --run tests/hil/plant_sim.sh)
      ;;
    daemon_motion)
      args=(--auto --timeout "$daemon_timeout_s" --start-allowance "$daemon_start_s" "${daemon_bins[@]}" --file "$build/hil/robot-relaxed.toml:robot.toml"
        --out "$out" --run tests/hil/daemon_motion.sh)
      ;;
    daemon_faults | daemon_link_down)
      args=(--auto --timeout "$daemon_timeout_s" --start-allowance "$daemon_start_s" "${daemon_bins[@]}" --file "$build/hil/robot-slow.toml:robot.toml"
        --out "$out" --run "tests/hil/$1.sh")
      ;;
    daemon_three_joints)
      args=(--auto --timeout "$daemon_timeout_s" --start-allowance "$three_joint_start_s" "${daemon_bins[@]}"
        --file "$build/hil/robot-three-joints.toml:robot.toml" --file "$three_joint_cache:grid-cache" --env GRID_CACHE_STRICT=1
        --out "$out" --run tests/hil/daemon_three_joints.sh)
      ;;
    daemon_hang)
      args=(--auto --timeout 150 --script-timeout "$hang_script_s" --start-allowance "$daemon_start_s" "${daemon_bins[@]}" --file "$build/hil/robot-slow.toml:robot.toml"
        --out "$out" --run tests/hil/daemon_hang.sh)
      ;;
    *) echo "run_hil: unknown case '$1'" >&2; exit 2 ;;
  esac
}

# Runs tools/vcan-vm for the case; sets $status, keeps its output in $log.
vcan_vm() {
  mkdir -p "$build/hil"
  rm -rf "$out"
  echo "+ tools/vcan-vm ${args[*]}"
  tools/vcan-vm "${args[@]}" >"$log" 2>&1
  status=$?
  cat "$log"
  echo "run_hil: tools/vcan-vm exited with status $status"
}

# Every frame the smoke script sends must be in the capture DIR/smoke.log, in candump -L form.
check_capture() {
  local capture=$1/smoke.log f
  [[ -s $capture ]] || fail smoke "no capture at $capture"
  for f in 0A080041#0102030405060708 123#DEADBEEF 001#11 '7FF#' 1FFFFFFF#CAFE 456#R 1F334455#CAFE000102030405; do
    grep -Eq "^\([0-9]+\.[0-9]{6}\) vcan0 $f\$" "$capture" || fail smoke "frame $f missing from $capture"
  done
  [[ $(grep -Ec '^\([0-9]+\.[0-9]{6}\) vcan0 321#[0-9A-F]{4}$' "$capture") -eq 20 ]] ||
    fail smoke "$capture does not hold the 20 cangen frames"
}

args_for "$1"
if ((print_only)); then
  echo "tools/vcan-vm ${args[*]}"
  exit 0
fi

case $1 in
  prepare)
    vcan_vm
    [[ $status -eq 0 ]] || fail prepare "kernel fetch or check failed"
    ;;
  smoke)
    vcan_vm
    [[ $status -eq 0 ]] || fail smoke "the guest script failed"
    check_capture "$out"
    grep -q "vcan_probe: ok" "$out/console.log" || fail smoke "vcan_probe did not report ok"
    ;;
  failure_propagates)
    vcan_vm
    [[ $status -eq 3 ]] || fail failure_propagates "expected status 3 from the failing guest script"
    grep -q "exit3: failing on purpose" "$out/console.log" || fail failure_propagates "the script's output is not in console.log"
    ;;
  script_timeout)
    vcan_vm
    [[ $status -eq 124 ]] || fail script_timeout "expected status 124 from a script that never ends"
    grep -q "script timed out after 3 s" "$log" || fail script_timeout "not stopped by --script-timeout"
    grep -q "left by the hung script" "$out/hang.txt" || fail script_timeout "\$EVIDENCE_DIR did not reach the host"
    grep -Eq "^task [0-9]+/[0-9]+ (dash|sh) state" "$out/timeout-tasks.txt" ||
      fail script_timeout "timeout-tasks.txt does not list the script's shell"
    ;;
  host_mode)
    vcan_vm
    [[ $status -eq 0 ]] || fail host_mode "host mode failed inside the VM"
    grep -q "auto: using host mode" "$out/console.log" || fail host_mode "--auto did not pick host mode"
    check_capture "$out/root"
    check_capture "$out/user"
    ;;
  plant_sim)
    mkdir -p "$build/hil"
    tests/hil/plant_sim_check.py setpoints "$build/hil/plant_sim.setpoints.log" || fail plant_sim "cannot write the setpoint stream"
    vcan_vm
    [[ $status -eq 0 ]] || fail plant_sim "the guest script failed"
    tests/hil/plant_sim_check.py check "$out" || fail plant_sim "the results do not hold (see the checks above)"
    ;;
  daemon_motion | daemon_faults | daemon_link_down)
    mkdir -p "$build/hil"
    if [[ $1 == daemon_motion ]]; then
      tests/hil/daemon_check.py hil-config config/reefscape-2025.toml "$build/hil/robot-relaxed.toml" relaxed
    else
      tests/hil/daemon_check.py hil-config config/reefscape-2025.toml "$build/hil/robot-slow.toml"
    fi || fail "$1" "cannot write the test config"
    # hil.daemon_motion relies on an enabled robot throughout and on a splice: a run in which the
    # whole guest stood still for the heartbeat timeout (0.5 s in its config) or longer, or in
    # which goal 2 ended before goal 3's plan came back, is void, and run again (at most twice
    # more). So is a link run whose goal was done before the link went down. The fault tests
    # retry their own goals instead (hil_guest.sh).
    for attempt in 1 2 3; do
      vcan_vm
      verdict=0
      if [[ $status -eq 124 ]]; then
        verdict="the guest script timed out"
      elif [[ $status -ne 0 ]]; then
        verdict="the guest script failed"
      elif ! tests/hil/daemon_check.py "${1#daemon_}" "$out" | tee "$out/check.txt"; then
        verdict="the results do not hold (see the checks above)"
      fi
      [[ $verdict == 0 ]] && break
      if [[ $1 == daemon_motion && $attempt -lt 3 ]] && tests/hil/daemon_check.py void "$out" 0.5; then
        echo "run_hil: attempt $attempt void (the guest stalled, or planned goal 3 too slowly to splice it): $verdict; running it again"
        continue
      fi
      if [[ $1 == daemon_link_down && $attempt -lt 3 ]] && tests/hil/daemon_check.py void-link "$out"; then
        echo "run_hil: attempt $attempt void (the guest stood still until the move was over, or the simulator coasted into an obstacle): $verdict; running it again"
        continue
      fi
      show_evidence "$out"
      fail "$1" "$verdict"
    done
    ;;
  daemon_three_joints)
    # The three-joint robot with the motion test's relaxed gates: a stall of the emulated guest
    # longer than the reference 0.1 s does not stop its moves (goal_done resends those that do).
    mkdir -p "$build/hil"
    # The robot as shipped (all its scenes and offset bands), gates relaxed.
    { cat config/reefscape-2025-elevator-pivot-wrist.toml
      printf '\n[daemon]\nheartbeat_timeout_s = 0.5\nstate_timeout_s = 0.5\n'; } >"$build/hil/robot-three-joints.toml"
    # Its grids, built natively by the binary the guest runs (2-3 s here; read back in under a second
    # when the cache already holds them): the guest's daemon reads them, ready in about 11 s (under
    # emulation the reef as drawn alone took 137 s to build, the three scenes as drawn 236 s). The
    # same files as tools/demo's: no [daemon] setting enters their key.
    tests/hil/grid_cache.sh "$build/daemon/app/cyber-plannerd" "$build/hil/robot-three-joints.toml" "$three_joint_cache" ||
      fail "$1" "the host could not build the grid cache"
    vcan_vm
    if [[ $status -ne 0 ]]; then
      show_evidence "$out"
      fail "$1" "the guest script failed or timed out (status $status)"
    fi
    # The guest's daemon started with the cache and built no grid itself.
    grep -q "planner ready in [0-9]* ms, grid cache .*/grid-cache$" "$out/daemon.log" ||
      fail "$1" "the guest's daemon did not use the grid cache (daemon.log: $(grep -m1 'planner ready' "$out/daemon.log"))"
    grep -qx "grid_cache_rebuilt=0" "$out/scenario.txt" || fail "$1" "the guest built grids itself (scenario.txt)"
    tests/hil/three_joint_check.py "$out" "$build/hil/robot-three-joints.toml" | tee "$out/check.txt"
    [[ ${PIPESTATUS[0]} -eq 0 ]] || { show_evidence "$out"; fail "$1" "the results do not hold (see the checks above)"; }
    ;;
  daemon_hang)
    # The runner's own test: a guest script that hangs with the daemon running must end as timed
    # out, and its evidence (the daemon's log, the step it hung in) must reach this output.
    mkdir -p "$build/hil"
    tests/hil/daemon_check.py hil-config config/reefscape-2025.toml "$build/hil/robot-slow.toml" ||
      fail "$1" "cannot write the test config"
    vcan_vm
    show_evidence "$out"
    [[ $status -eq 124 ]] || fail daemon_hang "expected status 124 from a hung script, got $status"
    grep -q "FAIL at step 'hanging on purpose" "$out/failure.txt" || fail daemon_hang "the failing step is not named"
    grep -q "cyber-plannerd: robot" "$out/daemon.log" || fail daemon_hang "the daemon's log did not reach the host"
    grep -Eq "^task [0-9]+/[0-9]+ cyber-plannerd state" "$out/timeout-tasks.txt" ||
      fail daemon_hang "timeout-tasks.txt does not list the daemon's threads"
    # The daemon was ready before the hang, under the start-up allowance, and the watchdog then
    # allowed the script its own limit (docs/testing.md, "Guest speed and start-up").
    grep -q "daemon_hang: daemon ready (holding)" "$out/script.log" || fail daemon_hang "the daemon's readiness is not in script.log"
    allowance=$(sed -n 's/^vcan-vm: guest speed: .*start-up allowance \([0-9]*\) s$/\1/p' "$log")
    [[ -n $allowance ]] || fail daemon_hang "no 'guest speed' line with the start-up allowance"
    ((allowance >= 30)) || fail daemon_hang "start-up allowance $allowance s, under its 30 s floor"
    grep -q "script still running $hang_script_s s after its start-up" "$log" ||
      fail daemon_hang "the watchdog did not stop the script $hang_script_s s after the daemon was ready"
    ;;
esac
echo "run_hil: $1 passed"
