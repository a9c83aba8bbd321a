#!/usr/bin/env bash
# The host's half of the grid cache hand-over (docs/testing.md, "Guest speed and start-up"): builds
# a robot's grids natively with the very cyber-plannerd binary the emulated guest runs, into a
# cache folder that tools/demo and hil.daemon_three_joints hand to the guest (tools/vcan-vm --file
# DIR:grid-cache; tests/hil/hil_guest.sh starts the guest's daemon with CACHE_DIRECTORY set to it).
# A cache file's key hashes the robot's geometry, the grid settings, the project's version and the
# compiler (docs/design.md, "The grid cache"), not the machine: the guest reads the host's files.
#
# Usage: tests/hil/grid_cache.sh CYBER_PLANNERD CONFIG DIR
#
# Runs CACHE_DIRECTORY=DIR CYBER_PLANNERD --config CONFIG --can none --lcm-url memq:// (no CAN, no
# network) until it logs "planner ready": by then it has read every file of DIR that checks and
# built and stored the others (missing, stale, corrupt). Then stops it with SIGTERM. Prints one
# line: the files, how many it built and read, its start-up. Its start-up when it built every
# file is kept in DIR/native-build-ms: what a guest that finds no valid file has to do, natively
# (tools/demo sizes its start-up allowance by it).
# Exit status: 0; 1 when the daemon failed or was not ready within 300 s; 2 on bad usage.
set -euo pipefail

(($# == 3)) || { echo "usage: $0 CYBER_PLANNERD CONFIG DIR" >&2; exit 2; }
daemon=$1
config=$2
dir=$3
ready_limit_s=300

fail() { echo "grid_cache: $*" >&2; exit 1; }

[[ -x $daemon ]] || fail "$daemon is not an executable"
[[ -f $config ]] || fail "$config: no such file"
mkdir -p "$dir"
# Each cache file with its inode: a file the daemon rebuilt is a new one (renamed over the old).
listing() { find "$dir" -maxdepth 1 -name '*.grids' -printf '%f %i\n' | LC_ALL=C sort; }
before=$(listing)
log=$(mktemp)
trap 'rm -f "$log"' EXIT
CACHE_DIRECTORY=$dir "$daemon" --config "$config" --can none --lcm-url memq:// >"$log" 2>&1 &
pid=$!
deadline=$((SECONDS + ready_limit_s))
until grep -q "planner ready in" "$log"; do
  if ! kill -0 "$pid" 2>/dev/null; then
    status=0
    wait "$pid" || status=$?
    fail "cyber-plannerd exited with status $status before it was ready: $(tail -n 3 "$log")"
  fi
  if ((SECONDS > deadline)); then
    kill -KILL "$pid" 2>/dev/null || true
    fail "cyber-plannerd was not ready within $ready_limit_s s: $(tail -n 3 "$log")"
  fi
  sleep 0.1
done
kill -TERM "$pid"
status=0
wait "$pid" || status=$?
((status == 0)) || fail "cyber-plannerd exited with status $status on SIGTERM: $(tail -n 3 "$log")"

ms=$(sed -n 's/.*planner ready in \([0-9]*\) ms.*/\1/p' "$log" | head -n 1)
after=$(listing)
total=$(grep -c . <<<"$after" || true)
built=$(comm -13 <(echo "$before") <(echo "$after") | grep -c . || true)
((total > 0)) || fail "cyber-plannerd stored no grid in $dir: $(head -n 3 "$log")"
((built < total)) || echo "$ms" >"$dir/native-build-ms"
echo "grid cache: $total files in $dir, $built built and $((total - built)) read natively (planner ready in $ms ms)"
