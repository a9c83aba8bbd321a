#!/usr/bin/env bash
# arm64.package: the arm64 Debian package that tools/package --arch arm64 wrote into
# BUILD/package, as docs/operations.md ("arm64 coprocessors") shows it: its control data
# (architecture, dependencies Debian 12 has for arm64), programs built for AArch64, unpacked into
# a scratch root with dpkg -x and run from there under the emulator (tools/arm64-run): the
# daemon's --help and one cyber-plan move.
#   package_run.sh BUILD_DIR
#   package_run.sh --print-doc-commands   the commands docs/operations.md must show
set -euo pipefail
source "$(dirname "$0")/../system/lib.sh"

commands() {
  deb="$build/package/cyber-planner_*_arm64.deb"
  root="$build/package/root"
  info="dpkg-deb --info $deb"
  unpack="dpkg -x $deb $root"
  daemon_help="tools/arm64-run $root/usr/bin/cyber-plannerd --help"
  plan="tools/arm64-run $root/usr/bin/cyber-plan --config $root/etc/cyber-planner/robot.toml --from 0.20,1.57 --to 1.97,5.17 --json"
}
if [[ ${1:-} == --print-doc-commands ]]; then
  build='build-arm64'
  commands
  printf '%s\n' "$info" "$unpack" "$daemon_help" "$plan"
  exit 0
fi
[[ $# -eq 1 ]] || { echo "usage: $0 BUILD_DIR | --print-doc-commands" >&2; exit 2; }
system_setup "$1"
commands

debs=("$build"/package/cyber-planner_*_arm64.deb)
[[ ${#debs[@]} -eq 1 && -f ${debs[0]} ]] || fail "expected one cyber-planner_*_arm64.deb in $build/package (tools/package --arch arm64)"
run_shown "$info" >"$build/package/info.txt"
field() { sed -n "s/^ $1: //p" "$build/package/info.txt"; }
[[ $(field Architecture) == arm64 ]] || fail "Architecture is '$(field Architecture)'"
depends=$(field Depends)
echo "Depends: $depends"
for needed in libc6 libstdc++6 liblcm1 libcairo2 libspdlog1.10 libtomlplusplus3; do
  [[ $depends == *"$needed"* ]] || fail "Depends lacks $needed: $depends"
done
# Every dependency is a package Debian 12 has for arm64 (apt's local index, no network), or a
# virtual one an arm64 package provides (libspdlog1.10 provides libspdlog1.10-fmt9).
IFS=',' read -ra alternatives <<<"$depends"
for dependency in "${alternatives[@]}"; do
  name=$(sed -E 's/^ *//; s/[ (|].*//' <<<"$dependency")
  apt-cache show --no-all-versions "$name:arm64" >/dev/null 2>&1 ||
    apt-cache showpkg "$name:arm64" | sed -n '/^Reverse Provides:/,$p' | grep -q ':arm64 ' ||
    fail "dependency '$name' is no Debian package for arm64"
done

rm -rf "$root"
run_shown "$unpack"
for program in cyber-plannerd cyber-plan cyber-goal cyber-can-decode cyber-plant-sim; do
  [[ -f $root/usr/bin/$program ]] || fail "$program missing from the package"
  machine=$(readelf -h "$root/usr/bin/$program" | sed -n 's/^ *Machine: *//p')
  [[ $machine == AArch64 ]] || fail "$program is built for '$machine'"
done

out=$(run_shown "$daemon_help" 2>&1) || fail "cyber-plannerd --help exited with status $?: $out"
grep -qi usage <<<"$out" || fail "cyber-plannerd --help printed no usage: $out"
out=$(run_shown "$plan") || fail "cyber-plan exited with status $?: $out"
python3 - "${out#*$'\n'}" <<'PY' || fail "cyber-plan printed: $out"
import json, sys
summary = json.loads(sys.argv[1])
assert summary['status'] == 'ok' and summary['duration_s'] > 0, summary
print('cyber-plan (arm64, packaged) STOW->L4: %.4f s, planned in %.1f ms under emulation'
      % (summary['duration_s'], summary['total_ms']))
PY
echo "arm64 package: $(basename "${debs[0]}") holds AArch64 programs that run under tools/arm64-run"
