# Shared guest-side helpers of the daemon HIL scripts (sourced; POSIX sh, dash + busybox). Work
# files go to the guest's tmpfs ($work) and are copied to $OUT_DIR by finish: one write per frame
# to the 9p share costs the emulated guest too much.

work=/tmp/hil
mkdir -p "$work"
pids=""

say() { echo "$script_name: $*"; }

# Copies the work files out, then exits with status $1 (message $2 on failure).
finish() {
  for pid in $pids; do kill "$pid" 2>/dev/null || true; done
  for pid in $pids; do wait "$pid" 2>/dev/null || true; done
  cp "$work"/* "$OUT_DIR"/ 2>/dev/null || true
  if [ "$1" -ne 0 ]; then
    echo "$script_name: FAIL: $2" >&2
    tail -n 20 "$work/daemon.log" >&2 2>/dev/null || true
  fi
  exit "$1"
}

fail() { finish 1 "$*"; }

# candump -L of the bus into $work/bus.log (-D: keep going while the interface is down), once it
# is seen listening.
start_bus_capture() {
  sync_frame=7FF#53594E43
  candump -L -D "$CAN_IFACE" >"$work/bus.log" &
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
  lcm-logger -f -q "$work/lcm.log" &
  logger=$!
}

# The plant simulator with extra arguments. It runs under SCHED_FIFO 40 (below the daemon's
# streamer at 50): it stands for the roboRIO and the motor controllers, separate hardware whose
# heartbeat does not wait for the daemon's other threads or this script's commands.
start_plant() {
  cyber-plant-sim --config "$FILES_DIR/robot.toml" --can "$CAN_IFACE" --log "$work/plant.csv" --realtime 40 "$@" \
    2>"$work/plant_sim.err" &
  plant=$!
}

start_daemon() {
  cyber-plannerd --config "$FILES_DIR/robot.toml" --can "$CAN_IFACE" >"$work/daemon.log" 2>&1 &
  daemon=$!
}

# Waits up to $3 seconds for a line matching $2 in file $1.
wait_for_line() {
  tries=0
  until grep -qs "$2" "$1"; do
    tries=$((tries + 1))
    [ "$tries" -le $(($3 * 50)) ] || fail "no '$2' in $(basename "$1") after $3 s"
    sleep 0.02
  done
}

# Sends goal N to T,THETA and waits for its final status; $3 is the exit status expected from
# cyber-goal (0 done, 5 cancelled).
goal() {
  status=0
  cyber-goal --to "$2" --id "$1" --timeout 60 >"$work/goal$1.out" 2>&1 || status=$?
  [ "$status" -eq "$3" ] || fail "goal $1 to $2: cyber-goal exited $status, expected $3 ($(cat "$work/goal$1.out"))"
  say "goal $1 to $2: $(tail -n 1 "$work/goal$1.out")"
}

# Stops the daemon and the simulator with SIGTERM (both must exit 0), then the recorders.
stop_all() {
  kill -TERM "$daemon" "$plant"
  daemon_status=0
  wait "$daemon" || daemon_status=$?
  plant_status=0
  wait "$plant" || plant_status=$?
  kill -INT "$logger"
  wait "$logger" || true
  kill "$dump"
  wait "$dump" || true
  [ "$daemon_status" -eq 0 ] || fail "cyber-plannerd exited with $daemon_status"
  [ "$plant_status" -eq 0 ] || fail "cyber-plant-sim exited with $plant_status"
}

# cyber-can-decode of the capture, in the guest, into $work/bus.csv (its summary in bus.decode.err).
decode_bus() {
  status=0
  cyber-can-decode --csv "$@" "$work/bus.log" >"$work/bus.csv" 2>"$work/bus.decode.err" || status=$?
  [ "$status" -eq 0 ] || fail "cyber-can-decode $* exited $status: $(cat "$work/bus.decode.err")"
  say "$(cat "$work/bus.decode.err")"
}
