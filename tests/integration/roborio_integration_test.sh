#!/usr/bin/env bash
# The roboRIO library's Java client and simulated robot against the real cyber-plannerd, in a
# network namespace of their own (as daemon_integration_test.sh does it):
#   roborio_integration_test.sh DAEMON CONFIG JAVA JUNIT_CONSOLE_JAR CLASSPATH TESTS_JAR
# The daemon runs with --can none and setpoint_echo_full_rate = true (desktop simulation:
# docs/roborio.md). Needs root (ip netns).
set -euo pipefail

daemon=$1 config=$2 java=$3 junit=$4 classpath=$5 tests_jar=$6
ns=cyber-roborio-$$
tmp=$(mktemp -d)
daemon_pid=

cleanup() {
  if [ -n "$daemon_pid" ]; then kill "$daemon_pid" 2>/dev/null || true; wait "$daemon_pid" 2>/dev/null || true; fi
  ip netns del "$ns" 2>/dev/null || true
  rm -rf "$tmp"
}
trap cleanup EXIT

ip netns add "$ns"
ip -n "$ns" link set lo up
ip -n "$ns" route add 224.0.0.0/4 dev lo

sed 's/^setpoint_echo_full_rate = false/setpoint_echo_full_rate = true/' "$config" >"$tmp/sim.toml"
grep -q '^setpoint_echo_full_rate = true' "$tmp/sim.toml" || { echo "FAIL: no setpoint_echo_full_rate key in $config"; exit 1; }
# The daemon stops motion when ARM_STATE is older than this: the Java side voids (and repeats once)
# a move during which its loop was starved that long, or the daemon logged such a stop
# (roborio/src/test/java/cyberplanner/roborio/sim/StarvationWatch.java).
state_timeout_s=$(sed -n 's/^state_timeout_s = \([0-9.]*\).*/\1/p' "$tmp/sim.toml")
[ -n "$state_timeout_s" ] || { echo "FAIL: no state_timeout_s key in $config"; exit 1; }
ip netns exec "$ns" "$daemon" --config "$tmp/sim.toml" --can none >"$tmp/daemon.log" 2>&1 &
daemon_pid=$!

rc=0
ip netns exec "$ns" "$java" -Dcyber.lcm.url='udpm://239.255.76.67:5810?ttl=0' \
  -Dcyber.state_timeout_s="$state_timeout_s" -Dcyber.daemon_log="$tmp/daemon.log" -jar "$junit" \
  --class-path "$classpath" --scan-class-path "$tests_jar" --include-tag daemon \
  --disable-banner --details=tree --disable-ansi-colors --fail-if-no-tests || rc=$?
kill -0 "$daemon_pid" 2>/dev/null || { echo "FAIL: the daemon died"; rc=1; }
if [ "$rc" -ne 0 ]; then echo "--- daemon log (last 40 lines)"; tail -n 40 "$tmp/daemon.log"; exit 1; fi
echo "daemon: motion stopped for a stale ARM_STATE $(grep -c 'ARM_STATE is stale' "$tmp/daemon.log") times"
echo PASS
