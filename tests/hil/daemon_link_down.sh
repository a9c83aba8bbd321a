#!/bin/sh
# Guest side of hil.daemon_link_down (inside tools/vcan-vm): 0.3 s into goal 1, vcan0 goes down
# for 2 s and up again. The daemon must keep running, report the failed writes, hold the measured
# position once the heartbeat is back, and serve goal 2. candump -D keeps recording across the
# outage. tests/hil/daemon_check.py link_down checks the recordings on the host.
set -eu
script_name=daemon_link_down
. "$FILES_DIR/hil_guest.sh"

# The link goes down only while the setpoints are moving.
link_down() { moving_now && ip link set "$CAN_IFACE" down; }

start_system --initial 0.2,1.57

during_motion link 1 1.97,5.17 0.3 link_down 0.2,1.57
sleep 2
ip link set "$CAN_IFACE" up
wait_goal "$id" 5
sleep 1
kill -0 "$daemon" || fail "cyber-plannerd is gone after the outage"
goal_done 2 0.2,1.57
sleep 0.5
stop_all
decode_bus --strict
finish 0
