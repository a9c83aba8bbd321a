#!/usr/bin/env bash
# The robot library's Java client and simulated robot against the real cyber-plannerd, in a
# network namespace of their own (as daemon_integration_test.sh does it), after the client's start
# in a namespace with no multicast route at all (NoRouteTest adds the route itself):
#   roborio_integration_test.sh DAEMON CONFIG JAVA JUNIT_CONSOLE_JAR CLASSPATH TESTS_JAR
# The daemon runs with --can none and setpoint_echo_full_rate = true (desktop simulation:
# docs/roborio.md). Needs root (ip netns).
set -euo pipefail

daemon=$1 config=$2 java=$3 junit=$4 classpath=$5 tests_jar=$6
ns=cyber-roborio-$$
bare=cyber-roborio-bare-$$
tmp=$(mktemp -d)
daemon_pid=

cleanup() {
  if [ -n "$daemon_pid" ]; then kill "$daemon_pid" 2>/dev/null || true; wait "$daemon_pid" 2>/dev/null || true; fi
  ip netns del "$ns" 2>/dev/null || true
  ip netns del "$bare" 2>/dev/null || true
  rm -rf "$tmp"
}
trap cleanup EXIT

# The LCM URL of the config, kept on the host (ttl=0): the daemon's and the client's.
url=$(sed -n 's/^lcm_url = "\(udpm:[^"?]*\).*/\1/p' "$config")?ttl=0
[[ $url == udpm://* ]] || { echo "FAIL: no udpm lcm_url in $config"; exit 1; }

ip netns add "$bare"
ip -n "$bare" link set lo up
ip netns exec "$bare" "$java" -Dcyber.lcm.url="${url%\?ttl=0}?ttl=1" -jar "$junit" \
  --class-path "$classpath" --scan-class-path "$tests_jar" --include-tag noroute \
  --disable-banner --details=tree --disable-ansi-colors --fail-if-no-tests || { echo "FAIL: the client without a route"; exit 1; }

ip netns add "$ns"
ip -n "$ns" link set lo up
ip -n "$ns" route add 224.0.0.0/4 dev lo

sed 's/^setpoint_echo_full_rate = false/setpoint_echo_full_rate = true/' "$config" >"$tmp/sim.toml"
grep -q '^setpoint_echo_full_rate = true' "$tmp/sim.toml" || { echo "FAIL: no setpoint_echo_full_rate key in $config"; exit 1; }
# The daemon stops motion when ARM_STATE is older than this: the Java side voids (and repeats once)
# a move during which its loop was starved that long, or the daemon logged such a stop
# (roborio/src/test/java/cyberplanner/roborio/sim/StarvationWatch.java).
# A config that leaves it to its default gets it written here, so the daemon and the test agree.
state_timeout_s=$(sed -n 's/^state_timeout_s = \([0-9.]*\).*/\1/p' "$tmp/sim.toml")
if [ -z "$state_timeout_s" ]; then
  state_timeout_s=0.25
  sed -i "s/^\[daemon\]\$/[daemon]\nstate_timeout_s = $state_timeout_s/" "$tmp/sim.toml"
  grep -q "^state_timeout_s = $state_timeout_s" "$tmp/sim.toml" || { echo "FAIL: no [daemon] table in $config"; exit 1; }
fi
ip netns exec "$ns" "$daemon" --config "$tmp/sim.toml" --can none >"$tmp/daemon.log" 2>&1 &
daemon_pid=$!

rc=0
ip netns exec "$ns" "$java" -Dcyber.lcm.url="$url" \
  -Dcyber.state_timeout_s="$state_timeout_s" -Dcyber.daemon_log="$tmp/daemon.log" -jar "$junit" \
  --class-path "$classpath" --scan-class-path "$tests_jar" --include-tag daemon \
  --disable-banner --details=tree --disable-ansi-colors --fail-if-no-tests || rc=$?
kill -0 "$daemon_pid" 2>/dev/null || { echo "FAIL: the daemon died"; rc=1; }
if [ "$rc" -ne 0 ]; then echo "--- daemon log (last 40 lines)"; tail -n 40 "$tmp/daemon.log"; exit 1; fi
echo "daemon: motion stopped for a stale ARM_STATE $(grep -c 'ARM_STATE is stale' "$tmp/daemon.log") times"
echo PASS
