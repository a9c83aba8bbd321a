#!/usr/bin/env bash
# system.lcm_record_replay: the recording and replay commands of docs/operations.md, for real,
# in a private network namespace. lcm_traffic publishes the six project types at 20 Hz;
# lcm-logger records 2 s of it; lcm-logplayer replays the log (whole, then filtered and faster)
# while lcm_traffic listens and counts what arrives and decodes. Then the log becomes a WPILOG
# for AdvantageScope (cyber-wpilog), which is listed and checked entry by entry against the
# recorded messages (lcm_to_wpilog_test on this log).
#   lcm_record_replay.sh BUILD_DIR
#   lcm_record_replay.sh --print-doc-commands    the commands docs/operations.md must show
set -euo pipefail
source "$(dirname "$0")/lib.sh"

# The commands as docs/operations.md shows them.
# The daemon's URL (docs/lcm.md), not LCM's own default (port 7667), so the commands name it.
record='lcm-logger --lcm-url='"'"'udpm://239.255.76.67:5810?ttl=0'"'"' --channel='"'"'ARM_.*'"'"' --force arm-session.lcmlog'
replay='lcm-logplayer --lcm-url='"'"'udpm://239.255.76.67:5810?ttl=0'"'"' arm-session.lcmlog'
replay_some='lcm-logplayer --lcm-url='"'"'udpm://239.255.76.67:5810?ttl=0'"'"' --speed=4 --regexp='"'"'ARM_(SETPOINT|TRAJECTORY)'"'"' arm-session.lcmlog'
replay_aside='lcm-logplayer --lcm-url='"'"'udpm://239.255.76.67:7668?ttl=0'"'"' arm-session.lcmlog'
convert='build/tools/cyber-wpilog/cyber-wpilog arm-session.lcmlog arm-session.wpilog'
list='build/tools/cyber-wpilog/cyber-wpilog --list arm-session.wpilog'
if [[ ${1:-} == --print-doc-commands ]]; then
  printf '%s\n' "$record" "$replay" "$replay_some" "$replay_aside" "$convert" "$list"
  exit 0
fi
[[ $# -eq 1 ]] || { echo "usage: $0 BUILD_DIR | --print-doc-commands" >&2; exit 2; }
system_setup "$1"
enter_netns "$src/tests/system/lcm_record_replay.sh" "$@"

url='udpm://239.255.76.67:5810?ttl=0'  # the daemon's default, which the commands above name
traffic=$build_abs/tests/system/lcm_traffic
work=$build_abs/system/record_replay
rm -rf "$work"
mkdir -p "$work"
cd "$work"
channels=(ARM_DAEMON_STATUS ARM_GOAL ARM_PLAN_STATUS ARM_SETPOINT ARM_STATE ARM_TRAJECTORY)

# Starts a listener in the background (counts go to $1, for at most $2 s, on URL $3 or $url)
# and waits until it is subscribed; its pid is $listener.
start_listener() {
  "$traffic" listen --lcm-url "${3:-$url}" --duration-s "$2" --quiet-s 1 >"$1" &
  listener=$!
  for _ in $(seq 100); do
    grep -qx listening "$1" && return 0
    sleep 0.1
  done
  fail "lcm_traffic listen did not start"
}

# Received count of a channel in counts file $1; fails unless every message decoded.
received() {
  local line
  line=$(grep "^$2 " "$1") || fail "no line for $2 in $1"
  read -r _ got decoded <<<"$line"
  [[ $got -eq $decoded ]] || fail "$2: $got received but only $decoded decoded as the published message"
  echo "$got"
}

# 1. Record while lcm_traffic publishes.
"$traffic" publish --lcm-url "$url" --rate-hz 20 --duration-s 4 >publisher.out &
publisher=$!
sleep 0.5
echo "+ $record"
(eval "exec $record") &
logger=$!
sleep 2
kill -INT "$logger"
wait "$logger" || fail "lcm-logger exited with status $? after SIGINT"
wait "$publisher" || fail "lcm_traffic publish failed"
[[ -s arm-session.lcmlog ]] || fail "lcm-logger wrote no arm-session.lcmlog"

# 2. Replay all of it: every channel arrives, about 2 s x 20 Hz each, and decodes.
start_listener all.counts 20
run_shown "$replay"
wait "$listener"
cat all.counts
for channel in "${channels[@]}"; do
  n=$(received all.counts "$channel")
  ((n >= 20 && n <= 60)) || fail "$channel: $n messages replayed, expected about 40 (2 s at 20 Hz)"
done

# 3. Replay two channels four times faster: only those arrive.
start_listener some.counts 20
run_shown "$replay_some"
wait "$listener"
cat some.counts
for channel in "${channels[@]}"; do
  n=$(received some.counts "$channel")
  case $channel in
    ARM_SETPOINT|ARM_TRAJECTORY) ((n >= 20)) || fail "$channel: only $n messages replayed" ;;
    *) ((n == 0)) || fail "$channel: $n messages replayed although --regexp leaves it out" ;;
  esac
done
# 4. Replay on another port: all of it arrives there, nothing on the default URL.
aside_url='udpm://239.255.76.67:7668?ttl=0'
start_listener default.counts 6
default_listener=$listener
start_listener aside.counts 20 "$aside_url"
run_shown "$replay_aside"
wait "$listener"
wait "$default_listener"
cat aside.counts
for channel in "${channels[@]}"; do
  n=$(received aside.counts "$channel")
  ((n >= 20)) || fail "$channel: only $n messages replayed on $aside_url"
  n=$(received default.counts "$channel")
  ((n == 0)) || fail "$channel: $n messages reached the default URL during a replay on $aside_url"
done

# 5. The recording as a WPILOG: an entry from each channel, every record decodable (--list
# fails otherwise), and every entry equal to the recorded messages.
ln -s "$build_abs" build
run_shown "$convert"
run_shown "$list" >wpilog.list
for entry in Elevator/SetpointMeters Elevator/MeasuredMeters Goal/RequestId PlanStatus/Status \
             Trajectory/ArmRadians Daemon/Mode Mechanism3d/Measured; do
  grep -q "^/CyberPlanner/$entry"$'\t' wpilog.list || fail "arm-session.wpilog has no /CyberPlanner/$entry"
done
CYBER_LCM_LOG=$work/arm-session.lcmlog "$build_abs/tests/unit/wpilog/lcm_to_wpilog_test" >wpilog.check ||
  { cat wpilog.check; fail "arm-session.wpilog differs from the recorded messages"; }
echo "lcm_record_replay: recorded and replayed all six channels, and converted them to WPILOG"
