#!/bin/sh
# Guest side of hil.daemon_faults (inside tools/vcan-vm): cyber-plannerd with the reference
# config and cyber-plant-sim on vcan0. Each fault hits a goal 0.3 s into its execution: the
# heartbeat lost for 0.5 s, a broadcast disable, ARM_STATE silent for 0.6 s; between the first two
# this script puts malformed and foreign frames on the bus while the daemon holds. A last goal
# must then run normally. tests/hil/daemon_check.py faults checks the recordings on the host.
set -eu
script_name=daemon_faults
. "$FILES_DIR/hil_guest.sh"

start_system --initial 0.2,1.57

during_motion heartbeat 1 1.97,5.17 0.3 "fault_if_moving heartbeat-stop" 0.2,1.57
sleep 0.5
fault heartbeat-resume
wait_goal "$id" 5
sleep 0.8
# Between two markers: heartbeat-id frames of the wrong length (3, counted as decode errors), a
# heartbeat remote request and frames with other ids (dropped by the daemon's receive filter), a
# setpoint id of the wrong length (counted by the simulator).
cansend "$CAN_IFACE" 7FF#47415242
cansend "$CAN_IFACE" 01011840#00000000120000
cansend "$CAN_IFACE" 01011840#
cansend "$CAN_IFACE" 01011840#00000000
cansend "$CAN_IFACE" 01011840#R
cansend "$CAN_IFACE" 123#DEADBEEF
cansend "$CAN_IFACE" 1FFFFFFF#0011223344556677
cansend "$CAN_IFACE" 040#0000000012000000
cansend "$CAN_IFACE" 0A080401#0102
cansend "$CAN_IFACE" 0A080803#00
cansend "$CAN_IFACE" 7FF#454E44
sleep 0.5
during_motion disable 2 0.2,1.57 0.3 "fault_if_moving disable" 1.97,5.17
wait_goal_noted "$id"
sleep 0.5
during_motion silent 3 1.97,5.17 0.3 "fault_if_moving silent" 0.2,1.57
sleep 0.6
fault state-resume
wait_goal "$id" 5
sleep 1.0
goal_done 4 0.2,1.57
sleep 0.5
kill -0 "$daemon" || fail "cyber-plannerd is gone"
stop_all
decode_bus
finish 0
