#!/bin/sh
# Guest side of hil.vcan_smoke (runs inside tools/vcan-vm): captures vcan0 with candump, sends
# known frames with cansend, cangen and our own C++ binary (vcan_probe), and checks that every
# frame is in the capture $OUT_DIR/smoke.log. run_hil.sh checks the same file again on the host.
set -eu

log=$OUT_DIR/smoke.log
sync_frame=7FF#53594E43 # "SYNC": candump is listening once it shows up
end_frame=7FF#454E44    # "END": everything sent before it has been captured
frames="0A080041#0102030405060708 123#DEADBEEF 001#11 7FF# 1FFFFFFF#CAFE 456#R"

# Waits until FRAME (sending it again each round when RESEND is set) is in the capture.
wait_for_frame() {
  tries=0
  until grep -qs " $CAN_IFACE $1\$" "$log"; do
    tries=$((tries + 1))
    if [ "$tries" -gt 600 ]; then
      echo "smoke: $1 never reached the capture" >&2
      exit 1
    fi
    [ -n "${2:-}" ] && cansend "$CAN_IFACE" "$1"
    sleep 0.05
  done
}

candump -L "$CAN_IFACE" >"$log" &
dump=$!
wait_for_frame "$sync_frame" resend

for f in $frames; do cansend "$CAN_IFACE" "$f"; done
cangen "$CAN_IFACE" -n 20 -g 1 -I 321 -L 2 -D i
"$BIN_VCAN_PROBE" "$CAN_IFACE"
cansend "$CAN_IFACE" "$end_frame"
wait_for_frame "$end_frame"
kill "$dump"
wait "$dump" || true

for f in $frames 1F334455#CAFE000102030405; do
  grep -q " $CAN_IFACE $f\$" "$log" || { echo "smoke: $f missing from the capture" >&2; exit 1; }
done
generated=$(grep -c " $CAN_IFACE 321#" "$log")
[ "$generated" -eq 20 ] || { echo "smoke: cangen sent 20 frames, captured $generated" >&2; exit 1; }
echo "smoke: all frames captured ($(wc -l <"$log") lines in smoke.log)"
