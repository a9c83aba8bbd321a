#!/bin/sh
# Guest side of hil.daemon_three_joints (inside tools/vcan-vm): cyber-plannerd and cyber-plant-sim
# on vcan0 with the three-joint robot (config/reefscape-2025-elevator-pivot-wrist.toml, gates
# relaxed as for hil.daemon_motion), recorded by candump and lcm-logger. Named moves, each from
# where the previous one ended: STOW -> L3 -> STOW holding a coral, then STOW -> NET -> STOW
# holding an algae. Each is sent again when the emulated guest stood still long enough to stop it
# (goal_done). The host (tests/hil/three_joint_check.py) checks tracking and final error.
set -eu
script_name=daemon_three_joints
. "$FILES_DIR/hil_guest.sh"

start_system --initial 0.05,1.5708,0
id=1
for move in L3:coral STOW:coral NET:algae STOW:algae; do
  pose=${move%%:*}
  pieces=${move#*:}
  note "move=$id:$pose:$pieces"
  goal_done "$id" "$pose" --config "$FILES_DIR/robot.toml" --pieces "$pieces"
  sleep 0.3
  id=$((id + 1))
done
sleep 0.5
stop_all
decode_bus --strict
finish 0
