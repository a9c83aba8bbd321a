#!/bin/sh
# Guest side of hil.daemon_link_down (inside tools/vcan-vm): while cyber-plannerd streams goal 1,
# vcan0 goes down for 2 s and up again. The daemon must keep running, report the failed writes,
# hold the measured position once the heartbeat is back, and serve goal 2. candump -D keeps
# recording across the outage. tests/hil/daemon_check.py link checks the recordings on the host.
set -eu
script_name=daemon_link_down
. "$FILES_DIR/hil_guest.sh"

start_bus_capture
start_lcm_log
start_plant --initial 0.2,1.57
start_daemon
pids="$daemon $plant $logger $dump"

cyber-goal --to 1.97,5.17 --id 1 --timeout 60 >"$work/goal1.out" 2>&1 &
goal1=$!
wait_for_line "$work/goal1.out" executing 60
sleep 0.3
ip link set "$CAN_IFACE" down
sleep 2
ip link set "$CAN_IFACE" up
status=0
wait "$goal1" || status=$?
[ "$status" -eq 5 ] || fail "goal 1 should end cancelled (exit 5), cyber-goal exited $status ($(cat "$work/goal1.out"))"
say "goal 1: $(tail -n 1 "$work/goal1.out")"
sleep 1
kill -0 "$daemon" || fail "cyber-plannerd is gone after the outage"
goal 2 0.2,1.57 0
sleep 0.5
stop_all
decode_bus --strict
finish 0
