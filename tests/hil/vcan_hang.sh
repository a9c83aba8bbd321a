#!/bin/sh
# Guest side of hil.vcan_script_timeout: a script that never ends and ignores SIGTERM, as a script
# stuck in a command that never returns does (its TERM trap waits for that command). tools/vcan-vm
# must stop it at --script-timeout, exit 124, and still bring out what it left in $EVIDENCE_DIR.
echo "hang: sleeping forever"
echo "left by the hung script" >"$EVIDENCE_DIR/hang.txt"
trap '' TERM
while :; do sleep 1; done
