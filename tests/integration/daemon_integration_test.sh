#!/usr/bin/env bash
# The real cyber-plannerd (--can none) and real LCM peers in a network namespace of their own.
#   daemon_integration_test.sh CASE DAEMON GOAL_TOOL PEER CONFIG [WALL_CLOCK_JUMP_SHIM]
# CASE: goal_done | bad_goals | flood | burst | garbage | sigterm | startup_errors | sighup |
#       lcm_lost | logs_full | wall_clock_jump | cancel | other_robot   (lcm_lost to
#       wall_clock_jump: docs/operations.md, "Faults"; cancel: docs/lcm.md, "Cancel and manual
#       override"; other_robot: CONFIG is another robot than the reference one, see the case)
# Needs root (ip netns). The namespace and every process started here are removed on exit, also
# on failure.
set -euo pipefail

case_name=$1 daemon=$2 goal=$3 peer=$4 config=$5 jump_shim=${6:-}
ns=cyber-test-$$
tmp=$(mktemp -d)
pids=()
daemon_pid=

cleanup() {
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done
  ip netns del "$ns" 2>/dev/null || true
  rm -rf "$tmp"
}
trap cleanup EXIT

fail() {
  echo "FAIL ($case_name): $*"
  if [ -f "$tmp/daemon.log" ]; then echo "--- daemon log (last 40 lines)"; tail -n 40 "$tmp/daemon.log"; fi
  exit 1
}

# Foreground only: a shell function run in the background is a subshell, and $! would be its pid
# rather than the program's. Background processes use `ip netns exec` directly (it execs).
in_ns() { ip netns exec "$ns" "$@"; }

setup_namespace() {
  ip netns add "$ns"
  ip -n "$ns" link set lo up
  ip -n "$ns" route add 224.0.0.0/4 dev lo
}

# Starts the daemon and a state publisher that follows the setpoint echo from STOW, then waits
# until the daemon holds (ARM_DAEMON_STATUS mode 1).
# DAEMON_LOG (default $tmp/daemon.log) is where its stdout and stderr go; DAEMON_ENV (VAR=VALUE
# words) is its extra environment.
start_daemon() {
  setup_namespace
  # shellcheck disable=SC2086
  ip netns exec "$ns" env ${DAEMON_ENV:-} "$daemon" --config "$config" --can none >"${DAEMON_LOG:-$tmp/daemon.log}" 2>&1 &
  daemon_pid=$!
  pids+=("$daemon_pid")
  # At a real-time priority below the streamer's (50), as the robot's own sender would be: at
  # normal priority a loaded machine starved it past state_timeout_s (0.25 s) now and then, and
  # the daemon rightly stopped the motion ("ARM_STATE is stale").
  ip netns exec "$ns" chrt -f 20 "$peer" state --at "${STATE_AT:-0.20,1.57}" --rate 100 >/dev/null 2>&1 &
  pids+=("$!")
  # The planner builds its grids at start-up: allow for a loaded machine.
  for _ in $(seq 1 600); do
    kill -0 "$daemon_pid" 2>/dev/null || fail "the daemon exited during start-up"
    if in_ns "$peer" status --timeout 0.5 >"$tmp/status" 2>/dev/null && grep -qx 'mode=1' "$tmp/status"; then
      return 0
    fi
    sleep 0.1
  done
  fail "the daemon did not start holding within 60 s"
}

udp_counter() {  # udp_counter NAME SNMP_FILE -> the Udp: counter NAME in a copy of /proc/net/snmp
  awk -v name="$1" '$1 == "Udp:" { if (!n) { for (i = 2; i <= NF; i++) col[$i] = i; n = 1 } else print $col[name] }' "$2"
}

# Returns once the watcher (watch_pid, output in $tmp/watch.out) has subscribed: statuses sent
# before that are never seen, and a loaded machine took longer than 0.5 s to start it.
wait_watching() {
  for _ in $(seq 1 600); do
    grep -q '^watching' "$tmp/watch.out" && return 0
    kill -0 "$watch_pid" 2>/dev/null || break
    sleep 0.05
  done
  cat "$tmp/watch.out"
  fail "the watcher did not start"
}

udp_drops() {  # udp_drops PID -> the kernel's drop count summed over PID's UDP sockets in the namespace
  local inodes
  inodes=$(find "/proc/$1/fd" -lname 'socket:*' -printf '%l\n' 2>/dev/null | tr -dc '0-9\n')
  in_ns cat /proc/net/udp | awk -v list="$inodes" '
    BEGIN { n = split(list, a, "\n"); for (i = 1; i <= n; i++) want[a[i]] = 1 }
    NR > 1 && ($10 in want) { sum += $13 }
    END { print sum + 0 }'
}

status_value() {  # status_value KEY -> value from a fresh ARM_DAEMON_STATUS
  in_ns "$peer" status --timeout 2 >"$tmp/status" || fail "no ARM_DAEMON_STATUS"
  sed -n "s/^$1=//p" "$tmp/status"
}

# expect_goal RC PATTERN ARGS...: cyber-goal exits with RC and prints a line matching PATTERN.
expect_goal() {
  local want=$1 pattern=$2
  shift 2
  local rc=0
  in_ns "$goal" "$@" --timeout 30 >"$tmp/goal.out" 2>&1 || rc=$?
  cat "$tmp/goal.out"
  [ "$rc" -eq "$want" ] || fail "cyber-goal $* exited $rc, expected $want"
  grep -q -- "$pattern" "$tmp/goal.out" || fail "cyber-goal $* printed no line matching '$pattern'"
}

# start_long_goal ID: cyber-goal in the background (goal_pid, output in $tmp/goal.out) for a long
# move, returning once the move executes.
start_long_goal() {
  ip netns exec "$ns" "$goal" --to 1.97,5.17 --id "$1" --timeout 30 >"$tmp/goal.out" 2>&1 &
  goal_pid=$!
  pids+=("$goal_pid")
  for _ in $(seq 1 300); do
    grep -q "request $1 executing" "$tmp/goal.out" && return 0
    sleep 0.01
  done
  fail "the goal never started executing"
}

# wait_mode MODE: polls ARM_DAEMON_STATUS until its mode is MODE (10 s at most).
wait_mode() {
  for _ in $(seq 1 100); do
    [ "$(status_value mode)" = "$1" ] && return 0
    sleep 0.1
  done
  fail "mode never became $1 (last: $(status_value mode))"
}

# SIGTERM, and the daemon exits 0.
stop_daemon_cleanly() {
  kill -TERM "$daemon_pid"
  local rc=0
  wait "$daemon_pid" || rc=$?
  [ "$rc" -eq 0 ] || fail "exit code $rc after SIGTERM"
}

case "$case_name" in
  goal_done)
    start_daemon
    expect_goal 0 "request 11 done" --to 1.97,5.17 --id 11
    # accepted -> planning -> executing -> done, in that order, and a trajectory.
    grep "request 11 " "$tmp/goal.out" | grep -v trajectory | awk '{print $3}' | tr -d ':' | tr '\n' ' ' >"$tmp/seq"
    [ "$(cat "$tmp/seq")" = "accepted planning executing done " ] || fail "status sequence: $(cat "$tmp/seq")"
    grep -q "request 11 trajectory: [0-9]* samples" "$tmp/goal.out" || fail "no trajectory"

    [ "$(status_value plans_succeeded)" -ge 1 ] || fail "plans_succeeded not counted"

    # Run as root, so real-time priority is granted (docs/design.md, "Threads and ownership"): the
    # streamer at SCHED_FIFO 50; the ARM_STATE receiver and LCM's receive thread under it at 45,
    # so that the daemon's own scheduling cannot make a fresh state look stale; all others
    # (event loop, the goal instance's LCM receive thread, planning worker, logger) SCHED_OTHER.
    policies=$(ps -L -o cls=,rtprio= -p "$daemon_pid" | awk '{print $1 "/" $2}' | sort | uniq -c | awk '{print $2 "x" $1}' | tr '\n' ' ')
    [ "$policies" = "FF/45x2 FF/50x1 TS/-x4 " ] || fail "thread policies (class/priority x count): $policies"
    ;;

  bad_goals)
    start_daemon
    expect_goal 3 "rejected: invalid input: position\[0\] (elevator) is not finite" --to nan,1.0 --id 21
    expect_goal 3 "rejected: invalid input: position\[1\] (arm) is not finite" --to 0.5,inf --id 22
    expect_goal 3 "rejected: goal out of range: position\[0\] (elevator) = 5 m is outside" --to 5,1.0 --id 23
    expect_goal 3 "rejected: invalid input: unknown scene 'moon'" --to 0.5,1.0 --scene moon --id 24
    expect_goal 3 "rejected: goal in collision" --to 0.0,4.71 --id 25
    # Pieces by the config's names, each once, at most MAX_PIECES; offsets within the scene's range.
    expect_goal 3 "rejected: invalid input: unknown game piece 'cone' in pieces\[0\] (this robot's: algae, coral)" \
      --to 0.58,2.97 --pieces cone --id 27
    expect_goal 3 "rejected: invalid input: game piece 'coral' is named twice" --to 0.58,2.97 --pieces coral,coral --id 28
    expect_goal 3 "rejected: invalid input: num_pieces = 5 is outside 0..4" --to 0.58,2.97 --pieces a,b,c,d,e --id 29
    expect_goal 3 "rejected: invalid input: scene_offset_m = 0.5 m is outside scene reef's offset range" \
      --to 0.58,2.97 --scene reef --scene-offset 0.5 --id 30
    # The message's joint count must be the robot's (docs/lcm.md, "Joints by index").
    expect_goal 3 "rejected: invalid input: num_joints = 3 but this robot has 2 joints (elevator, arm)" \
      --to 0.5,1.0,0.0 --id 32
    # A pose name the held set does not declare, resolved by the daemon's own configuration
    # (docs/lcm.md, "Named goals"): the reason lists the set's poses.
    expect_goal 3 'rejected: invalid input: no pose "HOLD_HIGH" for the held set "coral" (its poses: STOW, INTAKE, L1, L2, L3, L4, NET)' \
      --to HOLD_HIGH --pieces coral --id 33
    # Still serving, and a goal at an offset is planned there.
    expect_goal 0 "request 26 done" --to 0.58,2.97 --id 26
    expect_goal 0 "request 31 done" --to 0.20,1.57 --scene reef --scene-offset 0.2 --id 31
    # A named goal, sent as its name without --config: [poses.coral] L3 of the daemon's config.
    expect_goal 0 "request 34 done" --to L3 --pieces coral --id 34
    [ "$(status_value num_joints)" = 2 ] || fail "ARM_DAEMON_STATUS num_joints: $(status_value num_joints)"
    [ "$(status_value joint_names)" = "elevator,arm" ] || fail "joint_names: $(status_value joint_names)"
    ;;

  flood)
    # The daemon logs every status at debug level (one line per published status, after the send),
    # so a missing answer can be told apart: never published, or published and lost on the way.
    sed 's/^log_level = .*/log_level = "debug"/' "$config" >"$tmp/debug.toml"
    config=$tmp/debug.toml
    start_daemon
    # flood_round FIRST_ID: 1000 goals from FIRST_ID, the watcher's exit code in $rc.
    flood_round() {
      local first=$1
      in_ns cat /proc/net/snmp >"$tmp/snmp.before"
      # The watcher must see ~3000 status messages arrive in about a second. It queues them without
      # LCM's default limit of 30 per subscription (which dropped 1-2 of them now and then on a
      # busy machine, while the daemon's publish_failures stayed 0), forces a 4 MB socket receive
      # buffer (SO_RCVBUFFORCE: Debian's net.core.rmem_max of 212992 would cap LCM's
      # recv_buf_size) and runs at a real-time priority below the daemon's streamer (50), so it
      # drains its socket while builds compete.
      ip netns exec "$ns" chrt -f 20 "$peer" watch --first-id "$first" --count 1000 --timeout 60 \
        --rcvbuf-bytes 4194304 >"$tmp/watch.out" 2>&1 &
      watch_pid=$!
      pids+=("$watch_pid")
      wait_watching
      local received_before daemon_drops_before
      received_before=$(status_value goals_received)
      daemon_drops_before=$(udp_drops "$daemon_pid")
      # Exactly as many goals as the watcher waits for, however long a busy machine takes to send them.
      in_ns "$peer" flood --to 1.97,5.17 --to 0.58,2.97 --to 1.22,5.69 --rate 1000 --count 1000 --first-id "$first"
      rc=0
      wait "$watch_pid" || rc=$?
      in_ns cat /proc/net/snmp >"$tmp/snmp.after"
      cat "$tmp/watch.out"
      received=$(( $(status_value goals_received) - received_before ))
      daemon_drops=$(( $(udp_drops "$daemon_pid") - daemon_drops_before ))
      echo "daemon: received $received of the 1000 goals; kernel drops on its UDP sockets during the round $daemon_drops"
      # The namespace's UDP error counters (every socket in it: the daemon's and the peers').
      for counter in InErrors RcvbufErrors; do
        echo "namespace Udp $counter: $(udp_counter "$counter" "$tmp/snmp.before") -> $(udp_counter "$counter" "$tmp/snmp.after")"
      done
      # What the daemon logged for each id the watcher got no final status for.
      for id in $(sed -n 's/^no final status for request \([0-9]*\) .*/\1/p' "$tmp/watch.out"); do
        echo "--- daemon log for request $id"
        grep -E "(request|goal) $id[: ]" "$tmp/daemon.log" || echo "(nothing)"
      done
    }
    flood_round 1000
    if [ "$rc" -eq 3 ]; then
      # The kernel dropped datagrams on the watcher's own socket: the run says nothing about the
      # daemon. Once more; a missing status without a kernel drop fails.
      echo "VOID: the kernel dropped datagrams on the watcher's socket; flooding once more"
      flood_round 5000
    elif [ "$rc" -ne 0 ] && [ "$received" -lt 1000 ] && [ "$daemon_drops" -gt 0 ]; then
      # Goals the kernel dropped on the daemon's socket (its LCM thread starved on a loaded
      # machine) were never received, so never answered: once more, as above.
      echo "VOID: the kernel dropped goals on the daemon's socket; flooding once more"
      flood_round 5000
    fi
    echo "daemon: goals_received=$(status_value goals_received) decode_errors=$(status_value decode_errors)" \
      "publish_failures=$(status_value publish_failures)"
    [ "$rc" -eq 0 ] || fail "not every flooded goal got exactly one final status (publish_failures counts the daemon's failed sends)"
    kill -0 "$daemon_pid" || fail "the daemon died in the flood"
    expect_goal 0 "request 2001 done" --to 0.20,1.57 --id 2001
    echo "stream jitter p99 $(status_value stream_jitter_p99_us) us, overruns $(status_value stream_overruns)"
    ;;

  burst)
    # 100 goals reach the daemon while it is stopped (SIGSTOP): when it goes on, LCM's receive
    # thread queues them all at once, faster than the loop handles them. LCM's default of 30
    # queued messages per subscription would drop the rest without a word; every one must be
    # answered.
    start_daemon
    ip netns exec "$ns" chrt -f 20 "$peer" watch --first-id 3000 --count 100 --timeout 60 >"$tmp/watch.out" 2>&1 &
    watch_pid=$!
    pids+=("$watch_pid")
    wait_watching
    kill -STOP "$daemon_pid"
    in_ns "$peer" flood --to 1.97,5.17 --to 0.58,2.97 --rate 2000 --count 100 --first-id 3000
    sleep 0.3
    kill -CONT "$daemon_pid"
    rc=0
    wait "$watch_pid" || rc=$?
    cat "$tmp/watch.out"
    echo "daemon: goals_received=$(status_value goals_received) publish_failures=$(status_value publish_failures)"
    [ "$rc" -eq 0 ] || fail "not every goal of the burst got exactly one final status"
    ;;

  garbage)
    start_daemon
    in_ns "$peer" garbage --count 200
    sleep 0.5
    errors=$(status_value decode_errors)
    echo "decode_errors=$errors"
    [ "$errors" -ge 190 ] || fail "decode_errors $errors: garbage not counted"
    kill -0 "$daemon_pid" || fail "the daemon died of garbage"
    expect_goal 0 "request 31 done" --to 1.22,5.69 --id 31
    ;;

  sigterm)
    start_daemon
    start_long_goal 41
    start_ns=$(date +%s%N)
    kill -TERM "$daemon_pid"
    rc=0
    wait "$daemon_pid" || rc=$?
    elapsed_ms=$(( ($(date +%s%N) - start_ns) / 1000000 ))
    echo "daemon exited $rc after $elapsed_ms ms"
    [ "$rc" -eq 0 ] || fail "exit code $rc after SIGTERM"
    [ "$elapsed_ms" -lt 1000 ] || fail "took $elapsed_ms ms to exit"
    goal_rc=0
    wait "$goal_pid" || goal_rc=$?
    cat "$tmp/goal.out"
    [ "$goal_rc" -eq 5 ] || fail "cyber-goal exited $goal_rc, expected 5 (cancelled)"
    grep -q "cancelled: daemon shutting down" "$tmp/goal.out" || fail "no cancellation with a reason"
    grep -q "SIGTERM: holding the commanded position" "$tmp/daemon.log" || fail "no shutdown line in the log"
    ;;

  cancel)
    # ARM_CANCEL: a hold brakes a running move to rest (the real planner's fastest stop) and
    # cancels it; a release cancels the next one and stops the setpoints (mode 5) until a goal.
    # The stop is planned a budget ahead (the recent plan times), and under the sanitizers one
    # plan took 0.47 s: at 12 V the long move (0.71 s) could end before the stop's branch and the
    # daemon rightly held where it ended, with no stop to test. At 3 V the same move takes 3.0 s.
    sed 's/^voltage_limit_volts = .*/voltage_limit_volts = 3.0/' "$config" >"$tmp/slow.toml"
    grep -q '^voltage_limit_volts = 3.0' "$tmp/slow.toml" || fail "no voltage_limit_volts to lower in $config"
    config=$tmp/slow.toml
    start_daemon
    start_long_goal 81
    in_ns "$peer" cancel --id 81 --action hold
    goal_rc=0
    wait "$goal_pid" || goal_rc=$?
    cat "$tmp/goal.out"
    [ "$goal_rc" -eq 5 ] || fail "cyber-goal exited $goal_rc after a hold, expected 5 (cancelled)"
    grep -q "request 81 cancelled: cancelled by ARM_CANCEL: hold" "$tmp/goal.out" || fail "no hold reason"
    wait_mode 1
    grep -q "continues to its end" "$tmp/daemon.log" && fail "the hold found no stop: the move ran to its end"
    grep -q "ARM_CANCEL hold: request 81 brakes to rest in" "$tmp/daemon.log" || fail "no stop was planned"
    [ "$(status_value active_request_id)" = 81 ] || fail "the stop does not carry request 81"

    start_long_goal 82
    in_ns "$peer" cancel --id -1 --action release
    goal_rc=0
    wait "$goal_pid" || goal_rc=$?
    cat "$tmp/goal.out"
    [ "$goal_rc" -eq 5 ] || fail "cyber-goal exited $goal_rc after a release, expected 5 (cancelled)"
    grep -q "request 82 cancelled: cancelled by ARM_CANCEL: release (manual override)" "$tmp/goal.out" ||
      fail "no release reason"
    wait_mode 5
    [ "$(status_value motion_allowed)" = 0 ] || fail "motion allowed while released"
    # A stale cancel (82 is final) changes nothing: still released.
    in_ns "$peer" cancel --id 82 --action hold
    sleep 0.3
    [ "$(status_value mode)" = 5 ] || fail "a stale cancel ended the release"
    # The next goal ends the release.
    expect_goal 0 "request 83 done" --to 0.58,2.97 --id 83
    wait_mode 1
    stop_daemon_cleanly
    ;;

  sighup)
    # SIGHUP is ignored (docs/operations.md, "Signals"): a motion in progress finishes.
    start_daemon
    start_long_goal 61
    kill -HUP "$daemon_pid"
    goal_rc=0
    wait "$goal_pid" || goal_rc=$?
    cat "$tmp/goal.out"
    [ "$goal_rc" -eq 0 ] || fail "cyber-goal exited $goal_rc after SIGHUP, expected 0 (done)"
    kill -0 "$daemon_pid" || fail "SIGHUP killed the daemon"
    stop_daemon_cleanly
    ;;

  lcm_lost)
    # The network goes away under a running daemon (the multicast route is deleted): publishing
    # fails and is counted, nothing stops; when the route is back, it serves again.
    start_daemon
    ip -n "$ns" route del 224.0.0.0/4 dev lo
    sleep 1
    kill -0 "$daemon_pid" || fail "the daemon died without a route"
    ip -n "$ns" route add 224.0.0.0/4 dev lo
    failures=$(status_value publish_failures)
    echo "publish_failures=$failures while the route was gone"
    [ "$failures" -ge 5 ] || fail "publish failures not counted ($failures)"
    expect_goal 0 "request 71 done" --to 0.58,2.97 --id 71
    stop_daemon_cleanly
    ;;

  logs_full)
    # Logs that cannot be written: stderr on a full disk (/dev/full), then on a pipe whose reader
    # has gone (SIGPIPE is ignored). The daemon serves and stops cleanly either way.
    DAEMON_LOG=/dev/full start_daemon
    expect_goal 0 "request 81 done" --to 1.97,5.17 --id 81
    expect_goal 3 "rejected" --to 5,1.0 --id 82
    stop_daemon_cleanly
    ip netns del "$ns"
    mkfifo "$tmp/log.fifo"
    cat "$tmp/log.fifo" >/dev/null &
    reader_pid=$!
    DAEMON_LOG=$tmp/log.fifo start_daemon
    kill "$reader_pid"
    wait "$reader_pid" 2>/dev/null || true
    expect_goal 3 "rejected" --to nan,1.0 --id 83
    expect_goal 0 "request 84 done" --to 0.20,1.57 --id 84
    stop_daemon_cleanly
    ;;

  wall_clock_jump)
    # The daemon's wall clock jumps by +1 h, -1 h and +1 year every 0.3 s (an LD_PRELOAD shim;
    # the peers' clocks do not): motions, state ages and the stream do not notice, since they run
    # on CLOCK_MONOTONIC; only the utime stamps jump.
    # A sanitized daemon needs its ASan runtime first in the preload list.
    preload=$(ldd "$daemon" | awk '/libasan/ { printf "%s:", $3 }')$jump_shim
    DAEMON_ENV="LD_PRELOAD=$preload CYBER_WALL_JUMP_PERIOD_S=0.3" start_daemon
    expect_goal 0 "request 91 done" --to 1.97,5.17 --id 91
    expect_goal 0 "request 92 done" --to 0.20,1.57 --id 92
    jumped=0
    for _ in $(seq 1 8); do
      skew_s=$(( ($(status_value utime) - $(date +%s%6N)) / 1000000 ))
      [ "${skew_s#-}" -ge 3000 ] && jumped=1
      sleep 0.15
    done
    [ "$jumped" -eq 1 ] || fail "the daemon's wall clock never jumped (is the shim loaded?)"
    [ "$(status_value mode)" -eq 1 ] || fail "not holding after the jumps"
    age=$(status_value state_age_ms)
    echo "state_age_ms=$age with the wall clock jumping"
    awk -v a="$age" 'BEGIN { exit !(a >= 0 && a < 250) }' || fail "state age $age ms: the wall clock leaked in"
    stop_daemon_cleanly
    ;;

  startup_errors)
    # One clear line and a non-zero exit for each start-up problem (no namespace needed).
    one_line() {  # one_line RC PATTERN ARGS...
      local want=$1 pattern=$2
      shift 2
      local rc=0
      "$daemon" "$@" >"$tmp/out" 2>"$tmp/err" || rc=$?
      cat "$tmp/err"
      [ "$rc" -eq "$want" ] || fail "'$*' exited $rc, expected $want"
      [ "$(wc -l <"$tmp/err")" -eq 1 ] || [ "$want" -eq 2 ] || fail "'$*' printed more than one line"
      grep -q -- "$pattern" "$tmp/err" || fail "'$*' did not say '$pattern'"
    }
    "$daemon" --help | grep -q "cyber-plannerd \[--config FILE\]" || fail "--help"
    # Without --config the embedded reference robot loads (so start-up gets as far as LCM).
    one_line 1 "cyber-plannerd: cannot open LCM at 'bogus://nowhere'" --can none --lcm-url bogus://nowhere
    one_line 2 "unknown argument '--bogus'" --config "$config" --bogus
    printf 'name = "x"\n' >"$tmp/bad.toml"
    one_line 2 "cyber-plannerd: .*bad.toml" --config "$tmp/bad.toml" --can none
    one_line 1 "cyber-plannerd: cannot open LCM at 'bogus://nowhere'" --config "$config" --can none --lcm-url bogus://nowhere
    one_line 1 "cyber-plannerd: .*nosuchcan0" --config "$config" --can nosuchcan0 --lcm-url memq://
    # The configuration cannot be read: missing, a directory, or not readable by the daemon's user.
    one_line 2 "cannot open the configuration file (No such file or directory)" --config "$tmp/missing.toml"
    one_line 2 "is a directory, not a configuration file" --config "$tmp"
    cp "$config" "$tmp/secret.toml"
    chmod 600 "$tmp/secret.toml"
    chmod 755 "$tmp"
    rc=0
    setpriv --reuid=65534 --regid=65534 --clear-groups "$daemon" --config "$tmp/secret.toml" --can none \
      2>"$tmp/err" || rc=$?
    cat "$tmp/err"
    [ "$rc" -eq 2 ] && grep -q "cannot open the configuration file (Permission denied)" "$tmp/err" ||
      fail "an unreadable configuration: exit $rc"
    # LCM unreachable: a namespace without the multicast route (the default URL is udpm).
    ip netns add "$ns"
    ip -n "$ns" link set lo up
    rc=0
    in_ns "$daemon" --config "$config" --can none 2>"$tmp/err" || rc=$?
    cat "$tmp/err"
    [ "$rc" -eq 1 ] && [ "$(wc -l <"$tmp/err")" -eq 1 ] && grep -q "cannot open LCM at 'udpm://" "$tmp/err" ||
      fail "LCM without a multicast route: exit $rc"
    ;;

  other_robot)
    # Any robot file the daemon accepts runs it (issue 35: one without [planner] or [daemon],
    # tests/fixtures/minimal-robot.toml, takes every setting from its defaults; the three-joint
    # robot streams three joints): from the config's first named pose to each of its other poses
    # of the first pose set in turn, by name, each done with a trajectory of as many joints.
    mapfile -t poses < <(python3 -c 'import sys, tomllib
sets = tomllib.load(open(sys.argv[1], "rb"))["poses"]
name, table = next(iter(sets.items()))
print(",".join(f"{float(x):g}" for x in next(iter(table.values()))))
for pose in list(table)[1:3]: print(pose)' "$config")
    joints=$(python3 -c 'import sys, tomllib; print(len(tomllib.load(open(sys.argv[1], "rb"))["joints"]))' "$config")
    ((${#poses[@]} >= 2)) || fail "$config names fewer than two poses"
    # The state publisher sends as many joints as the pose has: the daemon holds (start_daemon)
    # only on states of its robot's joint count ($joints here).
    [[ ${poses[0]} =~ ^[^,]+(,[^,]+){$((joints - 1))}$ ]] || fail "the first pose ${poses[0]} is not $joints joints"
    STATE_AT=${poses[0]} start_daemon
    id=41
    for pose in "${poses[@]:1}"; do
      expect_goal 0 "request $id done" --config "$config" --to "$pose" --id "$id"
      grep -q "request $id trajectory: [0-9]* samples" "$tmp/goal.out" || fail "no trajectory for $pose"
      id=$((id + 1))
    done
    [ "$(status_value plans_succeeded)" -eq $((id - 41)) ] || fail "plans_succeeded is not $((id - 41))"
    ;;

  *)
    fail "unknown case"
    ;;
esac
echo "PASS ($case_name)"
