#!/bin/sh
# Guest side of hil.daemon_motion (inside tools/vcan-vm): cyber-plannerd and cyber-plant-sim on
# vcan0, recorded by candump and lcm-logger. Goal 1 moves STOW -> L4 to the end; goal 2 (L4 ->
# PROCESSOR) is replaced by goal 3 (-> STOW) as soon as it executes, and goal 3 must be spliced
# in. The host (tests/hil/daemon_check.py motion) checks position error, stream timing, the
# trajectories and the splice.
set -eu
script_name=daemon_motion
. "$FILES_DIR/hil_guest.sh"

start_system --initial 0.2,1.57

start_goal 1 1.97,5.17
wait_goal 1 0
sleep 0.5
start_goal 2 0.16,0.10
goal2=$goal_pid
wait_for_line "$work/goal2.out" "executing|$finals" 60
start_goal 3 0.2,1.57 --no-wait-daemon
wait_goal 3 0
goal_pid=$goal2
wait_goal 2 5
sleep 0.5
stop_all
decode_bus --strict
finish 0
