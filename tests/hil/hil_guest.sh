# Shared guest-side helpers of the daemon HIL scripts (sourced; POSIX sh, dash + busybox).
# Work files go to the guest's tmpfs ($work) and are copied to $OUT_DIR by finish: one write per
# frame to the 9p share costs the emulated guest too much. $work is tools/vcan-vm's EVIDENCE_DIR,
# which reaches the host after a timeout even when this script is stuck in a command that never
# returns. Progress lines (a few per run) go to the console and to $work/script.log.

work=${EVIDENCE_DIR:-$(mktemp -d "${TMPDIR:-/tmp}/hil.XXXXXX")}
control=$work/control
pids=""

# shellcheck disable=SC2154 # script_name: set by the script that sources this file
say() { echo "$script_name: $*" | tee -a "$work/script.log"; }

# Names what the script is doing now: a failure or a timeout reports it, with the evidence.
step_name="start"
step() {
  step_name=$*
  echo "step: $*" >>"$work/script.log"
}

# tools/vcan-vm's watchdog sends SIGTERM to a script past its time limit: save the evidence.
trap 'fail "timed out (SIGTERM from the watchdog)"' TERM

# The host-side check judges timing against the guest's own reference when it runs emulated.
if [ -e /vcan-vm/env ]; then echo "emulated=1" >>"$work/scenario.txt"; else echo "emulated=0" >>"$work/scenario.txt"; fi

# Records KEY=VALUE for the host-side check.
note() { echo "$1" >>"$work/scenario.txt"; }

# Copies the work files out, then exits with status $1 (message $2 on failure). The files go out
# first, and again once every process is stopped: stopping a stuck one takes a while.
finish() {
  cp "$work"/*.* "$OUT_DIR"/ 2>/dev/null || true
  for pid in $pids; do kill "$pid" 2>/dev/null || true; done
  for pid in $pids; do await_exit "$pid" 5; done
  cp "$work"/*.* "$OUT_DIR"/ 2>/dev/null || true
  if [ "$1" -ne 0 ]; then
    echo "$script_name: FAIL at step '$step_name': $2" >&2
    echo "$script_name: FAIL at step '$step_name': $2" >"$OUT_DIR/failure.txt"
    tail -n 20 "$work/daemon.log" >&2 2>/dev/null || true
  fi
  rm -rf "$work"
  exit "$1"
}

# Deadlines in seconds of the guest's clock (/proc/uptime, read without a fork), not counts of
# tries: under emulation each try's fork may take far longer than its sleep.
start_deadline() {
  read -r deadline_s _ </proc/uptime
  deadline_s=$((${deadline_s%.*} + $1))
}
past_deadline() {
  read -r now_s _ </proc/uptime
  [ "${now_s%.*}" -gt "$deadline_s" ]
}

# Waits up to $2 seconds for process $1 to exit, then kills it (SIGKILL); sets $exit_status, and
# $killed to 1 when it had to be killed.
await_exit() {
  start_deadline "$2"
  killed=0
  while kill -0 "$1" 2>/dev/null; do
    if past_deadline; then
      kill -KILL "$1" 2>/dev/null || true
      killed=1
      break
    fi
    sleep 0.05
  done
  exit_status=0
  wait "$1" 2>/dev/null || exit_status=$?
}

# candump -L of the bus into $work/bus.log (-D: keep going while the interface is down), once it
# is seen listening.
start_bus_capture() {
  step "starting the bus capture"
  sync_frame=7FF#53594E43
  candump -L -D "$CAN_IFACE" >"$work/bus.log" 2>"$work/candump.err" &
  dump=$!
  tries=0
  until grep -qs " $CAN_IFACE $sync_frame\$" "$work/bus.log"; do
    tries=$((tries + 1))
    [ "$tries" -le 600 ] || fail "candump never started"
    cansend "$CAN_IFACE" "$sync_frame"
    sleep 0.05
  done
}

start_lcm_log() {
  # The daemon's URL: the script's LCM_URL when it sets one (its robot.toml's lcm_url), else the
  # reference config's (docs/lcm.md).
  lcm-logger -f -q --lcm-url="${LCM_URL:-udpm://239.255.76.67:5810?ttl=0}" "$work/lcm.log" &
  logger=$!
}

# The plant simulator with extra arguments, its faults also driven through the FIFO $control. It
# runs under SCHED_FIFO 40 (below the daemon's streamer at 50): it stands for the roboRIO and the
# motor controllers, separate hardware whose heartbeat does not wait for the daemon's other
# threads or this script's commands.
start_plant() {
  step "starting cyber-plant-sim"
  mkfifo "$control"
  cyber-plant-sim --config "$FILES_DIR/robot.toml" --can "$CAN_IFACE" --log "$work/plant.csv" --realtime 40 \
    --control "$control" "$@" 2>"$work/plant_sim.err" &
  plant=$!
}

# The grid cache the host built natively (tests/hil/grid_cache.sh), handed over as --file
# DIR:grid-cache: the daemon reads its grids from it instead of building them, many times slower,
# in the guest. A file whose key does not match (another robot, binary or planner version) or that
# fails its checks is rebuilt by the daemon and renamed over the old one: a new inode.
grid_cache=$FILES_DIR/grid-cache
# With GRID_CACHE_STRICT=1 (the HIL tests) a file rebuilt in the guest fails the run at once.
GRID_CACHE_STRICT=${GRID_CACHE_STRICT:-0}

# Each cache file's inode and name, one a line (ls sorts them by name).
# shellcheck disable=SC2012 # our own file names, no blanks
cache_listing() { ls -i "$grid_cache" 2>/dev/null | sed -n 's/^ *\([0-9]* .*\.grids\)$/\1/p'; }

# The cache files rebuilt in the guest so far (names, space-separated): new ones and those whose
# inode changed since the daemon started.
cache_rebuilt() {
  cache_listing | CACHE_BEFORE=$cache_before awk 'BEGIN { n = split(ENVIRON["CACHE_BEFORE"], b, "\n"); for (i = 1; i <= n; i++) old[b[i]] = 1 }
    !($0 in old) { printf "%s%s", sep, $2; sep = " " }'
}

start_daemon() {
  step "starting cyber-plannerd"
  read -r daemon_started_s _ </proc/uptime
  daemon_started_s=${daemon_started_s%.*}
  if [ -d "$grid_cache" ]; then
    cache_before=$(cache_listing)
    say "grid cache: $(printf '%s\n' "$cache_before" | grep -c .) files from the host in $grid_cache (CACHE_DIRECTORY)"
    CACHE_DIRECTORY=$grid_cache cyber-plannerd --config "$FILES_DIR/robot.toml" --can "$CAN_IFACE" >"$work/daemon.log" 2>&1 &
  else
    cyber-plannerd --config "$FILES_DIR/robot.toml" --can "$CAN_IFACE" >"$work/daemon.log" 2>&1 &
  fi
  daemon=$!
}

# Says which cache files the daemon has rebuilt so far (a cache miss: each costs what it would
# without a cache), when that changed; fails the run on one in strict mode.
cache_misses_said=""
check_cache() {
  [ -d "$grid_cache" ] || return 0
  rebuilt=$(cache_rebuilt)
  [ -n "$rebuilt" ] || return 0
  [ "$rebuilt" != "$cache_misses_said" ] || return 0
  new=""
  for name in $rebuilt; do
    case " $cache_misses_said " in *" $name "*) ;; *) new="$new${new:+ }$name" ;; esac
  done
  cache_misses_said=$rebuilt
  # shellcheck disable=SC2086 # the names, counted
  set -- $rebuilt
  say "grid cache MISS: the daemon has built $new itself in the guest ($# so far; slower: the host's file was missing or did not match)"
  [ "$GRID_CACHE_STRICT" -eq 0 ] || fail "grid cache miss in the guest ($rebuilt) with GRID_CACHE_STRICT=1"
}

# Waits until the daemon takes goals: its first hold, once it has a state and the robot's enabled
# heartbeat (a goal sent before it is refused; its READY=1 comes earlier). Its start-up runs many
# times slower in the emulated guest and slower still on a busy host, so the deadline is
# tools/vcan-vm's start-up allowance, scaled to the guest's measured speed (docs/testing.md,
# "Guest speed and start-up"); 60 s without one.
await_ready() {
  ready_s=${VCAN_START_S:-0}
  [ "$ready_s" -gt 0 ] || ready_s=60
  step "waiting up to $ready_s s for the daemon's first hold"
  start_deadline "$ready_s"
  checked_s=0
  until grep -Eqs "holding [^ ]+ -?[0-9]" "$work/daemon.log"; do
    if past_deadline; then
      check_cache
      fail "no 'holding' in daemon.log after $ready_s s${cache_misses_said:+ (grid cache misses: $cache_misses_said)}"
    fi
    # A cache miss is said as it happens (a look every 10 s of the guest's clock: it forks).
    if [ "${now_s%.*}" -ge $((checked_s + 10)) ]; then
      checked_s=${now_s%.*}
      check_cache
    fi
    sleep 0.05
  done
  check_cache
  # The start-up is over: tools/vcan-vm's watchdog gives back the rest of the allowance.
  [ -z "${VCAN_STARTED_FILE:-}" ] || : >"$VCAN_STARTED_FILE"
  read -r now_s _ </proc/uptime
  say "daemon ready (holding) $((${now_s%.*} - daemon_started_s)) s after its start (deadline $ready_s s; guest ${VCAN_SLOWDOWN:-?}x slower than natively)"
  # The daemon's own line: its planner's start-up and the cache folder it used.
  say "$(grep -o 'planner ready in .*' "$work/daemon.log" | head -n 1)"
  if [ -d "$grid_cache" ]; then
    total=$(cache_listing | grep -c . || true)
    rebuilt=$(cache_rebuilt)
    # shellcheck disable=SC2086 # the names, counted
    set -- $rebuilt
    note "grid_cache_files=$total"
    note "grid_cache_rebuilt=$#"
    if [ "$#" -eq 0 ]; then
      say "grid cache: all $total files read, none built in the guest"
    else
      say "grid cache: $# of $total files built in the guest (cache miss: see above)"
    fi
  fi
}

# The whole set-up of a daemon run: bus capture, LCM log, the simulator (with arguments "$@") and
# the daemon, ready for goals; finish and stop_all stop them.
start_system() {
  start_bus_capture
  start_lcm_log
  start_plant "$@"
  start_daemon
  pids="$daemon $plant $logger $dump"
  await_ready
}

# Injects fault KIND now.
fault() { echo "$1" >"$control"; }

# Sends control line $1 and waits for the simulator's answer in its log: returns 0 when the new
# line matches the extended regex $2, 1 when it matches $3.
control_answer() {
  step "asking the simulator '$1'"
  before=$(grep -Ec "$2|$3" "$work/plant_sim.err" || true)
  echo "$1" >"$control"
  start_deadline 5
  while [ "$(grep -Ec "$2|$3" "$work/plant_sim.err" || true)" -le "$before" ]; do
    ! past_deadline || fail "no answer from the simulator to '$1' within 5 s"
    sleep 0.02
  done
  grep -E "$2|$3" "$work/plant_sim.err" | tail -n 1 | grep -Eq "$2"
}

# Injects fault KIND only if the setpoints are moving right now (the simulator decides on the
# frames it sees); returns 1 when it did not.
fault_if_moving() { control_answer "$1 if-moving" "fault $1 \(control\)" "$1 if-moving skipped"; }

# Returns 0 when the simulator saw a moving setpoint within the last 20 ms.
moving_now() { control_answer probe "probe: moving" "probe: not moving"; }


# Waits up to $3 seconds (start_deadline) for a line matching the extended regex $2 in file $1.
wait_for_line() {
  step "waiting up to $3 s for '$2' in $(basename "$1")"
  start_deadline "$3"
  until grep -Eqs "$2" "$1"; do
    ! past_deadline || fail "no '$2' in $(basename "$1") after $3 s"
    sleep 0.02
  done
}

finals='request [0-9]+ (done|rejected|failed|cancelled)'

# How long a goal may take from being sent to its final status, planning in the emulated guest
# included (a plan of ~0.1 s natively takes 1-8 s there; docs/testing.md).
GOAL_TIMEOUT_S=90

# Starts goal $1 to $2 in the background (pid in $goal_pid); more cyber-goal options may follow.
start_goal() {
  id_=$1
  to_=$2
  shift 2
  step "goal $id_ to $to_"
  cyber-goal --to "$to_" --id "$id_" --timeout "$GOAL_TIMEOUT_S" "$@" >"$work/goal$id_.out" 2>&1 &
  goal_pid=$!
}

# Waits for the background goal $1 and notes how it ended (the host checks it).
wait_goal_noted() {
  step "waiting for goal $1 to end"
  status=0
  wait "$goal_pid" || status=$?
  say "goal $1: $(tail -n 1 "$work/goal$1.out")"
}

# Waits for the background goal $1; fails unless cyber-goal exits $2 (0 done, 5 cancelled).
wait_goal() {
  step "waiting for goal $1 to end (cyber-goal exit $2 expected)"
  status=0
  wait "$goal_pid" || status=$?
  [ "$status" -eq "$2" ] || fail "goal $1: cyber-goal exited $status, expected $2 ($(cat "$work/goal$1.out"))"
  say "goal $1: $(tail -n 1 "$work/goal$1.out")"
}

# Starts goal $2 to $3 and, once it has been executing for $4 s, runs the command $5 (a fault
# through fault_if_moving, or a link change after moving_now), noting "$1=ID"; the goal's id is
# left in $id. Under emulation the guest sometimes stands still long enough for the daemon to stop
# on a stale heartbeat by itself; when the goal was no longer moving the command is not carried
# out and the goal is sent again with the id + 100 (noted as retry=ID), up to three times,
# alternating its target with $6 so that each try is a long move again.
during_motion() {
  id=$2
  target=$3
  for _try in 1 2 3; do
    start_goal "$id" "$target"
    wait_for_line "$work/goal$id.out" "executing|$finals" "$GOAL_TIMEOUT_S"
    sleep "$4"
    if ! grep -Eqs "$finals" "$work/goal$id.out" && $5; then
      note "$1=$id"
      return 0
    fi
    wait "$goal_pid" || true
    say "goal $id was not moving any more for '$5': $(tail -n 1 "$work/goal$id.out")"
    note "retry=$id"
    id=$((id + 100))
    if [ "$target" = "$3" ]; then target=$6; else target=$3; fi
  done
  fail "no goal was still moving $4 s after it started executing, in three tries"
}

# Goal $1 to $2 that must end done; sent again (id + 100, noted retry=ID) when the daemon stopped
# it on a stale heartbeat or state (see during_motion), up to three times.
goal_done() {
  id=$1
  for _try in 1 2 3; do
    start_goal "$id" "$2"
    step "waiting for goal $id to end"
    status=0
    wait "$goal_pid" || status=$?
    say "goal $id: $(tail -n 1 "$work/goal$id.out")"
    if [ "$status" -eq 0 ]; then
      note "done=$id"
      return 0
    fi
    grep -Eqs "cancelled: motion stopped.*(heartbeat|stale)" "$work/goal$id.out" ||
      fail "goal $id to $2: cyber-goal exited $status ($(cat "$work/goal$id.out"))"
    note "retry=$id"
    id=$((id + 100))
  done
  fail "goal $1 to $2 never finished in three tries"
}

# Waits up to 10 s for process $1 ($2 names it) to exit; sets $exit_status. Kills it after that.
reap() {
  await_exit "$1" 10
  [ "$killed" -eq 0 ] || fail "$2 did not exit within 10 s of its signal"
}

# CPU time (clock ticks: user, system) of each process so far, and the guest's uptime, for the
# host-side report: who kept the emulated CPU busy.
cpu_report() {
  {
    echo "uptime $(cut -d' ' -f1 /proc/uptime)"
    for name_pid in "cyber-plannerd:${daemon:-0}" "cyber-plant-sim:${plant:-0}" "lcm-logger:${logger:-0}" "candump:${dump:-0}"; do
      echo "${name_pid%%:*} $(cut -d' ' -f14,15,22 "/proc/${name_pid#*:}/stat" 2>/dev/null)"
    done
    # The daemon's threads one by one (fields: tid, scheduling policy, user and system ticks).
    for task in /proc/"${daemon:-0}"/task/*; do
      echo "thread ${task##*/} $(cut -d' ' -f41 "$task/stat") $(cut -d' ' -f14,15 "$task/stat")"
    done
  } >"$work/cpu.txt"
}

# Copies what goes wrong before stop_all too: the CPU report and the guest's kernel messages.
fail() {
  [ -n "${daemon:-}" ] && cpu_report 2>/dev/null
  finish 1 "$*"
}

# Stops the daemon and the simulator with SIGTERM (both must exit 0), then the recorders.
stop_all() {
  step "stopping the daemon, the simulator and the recorders"
  cpu_report
  kill -TERM "$daemon" "$plant"
  reap "$daemon" cyber-plannerd
  [ "$exit_status" -eq 0 ] || fail "cyber-plannerd exited with $exit_status on SIGTERM"
  reap "$plant" cyber-plant-sim
  [ "$exit_status" -eq 0 ] || fail "cyber-plant-sim exited with $exit_status on SIGTERM"
  kill -INT "$logger"
  reap "$logger" lcm-logger
  kill "$dump"
  reap "$dump" candump
  pids=""
}

# cyber-can-decode of the capture, in the guest, into $work/bus.csv (its summary in bus.decode.err).
decode_bus() {
  step "decoding the capture (cyber-can-decode $*)"
  status=0
  cyber-can-decode --csv "$@" "$work/bus.log" >"$work/bus.csv" 2>"$work/bus.decode.err" || status=$?
  [ "$status" -eq 0 ] || fail "cyber-can-decode $* exited $status: $(cat "$work/bus.decode.err")"
  say "$(cat "$work/bus.decode.err")"
}
