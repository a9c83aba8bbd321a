#!/bin/sh
# Guest side of hil.vcan_failure_propagates: a failing test script. tools/vcan-vm must exit 3.
echo "exit3: failing on purpose with status 3"
exit 3
