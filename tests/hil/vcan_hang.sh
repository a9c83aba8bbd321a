#!/bin/sh
# Guest side of hil.vcan_script_timeout: a script that never ends. tools/vcan-vm must stop it at
# --script-timeout and exit 124.
echo "hang: sleeping forever"
while :; do sleep 1; done
