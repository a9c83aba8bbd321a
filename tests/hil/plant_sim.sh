#!/bin/sh
# Guest side of hil.plant_sim (runs inside tools/vcan-vm): cyber-plant-sim alone on vcan0.
# canplayer replays a setpoint stream made on the host (an elevator move, the arm holding), the
# simulator injects each fault once on its motion-relative schedule, and candump and lcm-logger
# record the bus and LCM. Everything is written to the guest's tmpfs first (a write per frame to
# the 9p share costs the emulated guest too much) and copied to $OUT_DIR at the end;
# tests/hil/plant_sim_check.py checks it there on the host.
set -eu

work=/tmp/plant_sim
mkdir -p "$work"
bus=$work/bus.log
sync_frame=7FF#53594E43

candump -L "$CAN_IFACE" >"$bus" &
dump=$!
tries=0
until grep -qs " $CAN_IFACE $sync_frame\$" "$bus"; do
  tries=$((tries + 1))
  [ "$tries" -le 600 ] || { echo "plant_sim: candump never started" >&2; exit 1; }
  cansend "$CAN_IFACE" "$sync_frame"
  sleep 0.05
done
lcm-logger -f -q --lcm-url='udpm://239.255.76.67:5810?ttl=0' "$work/lcm.log" &  # the daemon's URL (docs/lcm.md)
logger=$!

cyber-plant-sim --can "$CAN_IFACE" --realtime 40 --initial 0.5,1.57 --log "$work/plant.csv" --duration 30 \
  --fault heartbeat-stop@motion+0.4 --fault heartbeat-resume@motion+0.6 \
  --fault heartbeat-disabled@motion+0.8 --fault heartbeat-enabled@motion+0.9 \
  --fault silent@motion+1.0 --fault state-resume@motion+1.2 \
  --fault disable@motion+1.3 --fault exit@motion+2.5 2>"$work/plant_sim.err" &
sim=$!
# The replay starts once the simulator's socket is open (it logs "running on" then).
tries=0
until grep -qs "running on" "$work/plant_sim.err"; do
  tries=$((tries + 1))
  [ "$tries" -le 600 ] || { echo "plant_sim: the simulator never started" >&2; exit 1; }
  sleep 0.05
done
# canplayer at SCHED_FIFO 30 keeps its 5 ms spacing better while the simulator (and the guest)
# is busy; it stands in for the daemon's real-time streamer thread.
chrt -f 30 canplayer -I "$FILES_DIR/setpoints.log" "$CAN_IFACE=can0"
# Our setpoint ids with a wrong length (counted as malformed), and frames the simulator's receive
# filter drops: a remote request with our id, another id, the daemon's status id.
cansend "$CAN_IFACE" 0A080401#0102
cansend "$CAN_IFACE" 0A080402#
cansend "$CAN_IFACE" 0A080401#R
cansend "$CAN_IFACE" 123#DEADBEEF
cansend "$CAN_IFACE" 0A080403#0102030405060708

status=0
wait "$sim" || status=$?
kill -INT "$logger"
wait "$logger" || true
kill "$dump"
wait "$dump" || true
cp "$work"/* "$OUT_DIR"/
cat "$work/plant_sim.err"
[ "$status" -eq 0 ] || { echo "plant_sim: cyber-plant-sim exited with $status" >&2; exit 1; }
echo "plant_sim: done ($(wc -l <"$bus") frames captured)"
