#!/bin/sh
# Guest side of hil.daemon_hang, the runner's own test: with the daemon and the simulator running,
# the script hangs. tools/vcan-vm's watchdog must stop it, and the evidence (daemon log, the step
# it hung in) must reach the host (tests/hil/run_hil.sh checks both).
set -eu
script_name=daemon_hang
. "$FILES_DIR/hil_guest.sh"

start_system --initial 0.2,1.57
step "hanging on purpose"
sleep 100000 &
wait $!
finish 0
