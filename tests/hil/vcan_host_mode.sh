#!/bin/sh
# Guest side of hil.vcan_host_mode: the VM's kernel has vcan, so inside it tools/vcan-vm's host
# mode can be exercised for real, as it runs on a Linux laptop after `sudo modprobe vcan`:
#   1. as root, --auto must choose host mode and the smoke script must pass;
#   2. as an unprivileged user (nobody), --host must pass too (it then adds a user namespace);
#   3. a failing script must make host mode exit with the script's status (3).
# Needs (given with --bin/--file by run_hil.sh): bash, unshare, timeout, setpriv, vcan_probe,
# tools/vcan-vm as $FILES_DIR/vcan-vm and the smoke and exit3 scripts.
set -eu

vcan_vm() { bash "$FILES_DIR/vcan-vm" --cache /tmp/vcan-cache --bin "$BIN_VCAN_PROBE" "$@"; }

echo "host_mode: 1. root, --auto"
vcan_vm --auto --out "$OUT_DIR/root" --run "$FILES_DIR/vcan_smoke.sh"

echo "host_mode: 2. nobody, --host"
mkdir -p "$OUT_DIR/user" /tmp/user
chmod 777 "$OUT_DIR/user" /tmp/user
TMPDIR=/tmp/user setpriv --reuid=65534 --regid=65534 --clear-groups \
  bash "$FILES_DIR/vcan-vm" --host --cache /tmp/user/cache --bin "$BIN_VCAN_PROBE" \
  --out "$OUT_DIR/user" --run "$FILES_DIR/vcan_smoke.sh"

echo "host_mode: 3. failing script, --host"
status=0
vcan_vm --host --out "$OUT_DIR/fail" --run "$FILES_DIR/vcan_exit3.sh" || status=$?
[ "$status" -eq 3 ] || { echo "host_mode: expected status 3 from a failing script, got $status" >&2; exit 1; }
echo "host_mode: all passed"
