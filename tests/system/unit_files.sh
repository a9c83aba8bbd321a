#!/usr/bin/env bash
# The systemd and networkd files the project ships (systemd/), checked by systemd's own tools.
#   unit_files.sh verify BUILD_DIR
#       installs the build into a staging root (cmake --install, DESTDIR) and runs
#       `systemd-analyze verify --root=STAGE cyber-planner.service`, which must print nothing.
#       verify needs ExecStart's binary in the root.
#   unit_files.sh security BUILD_DIR
#       `systemd-analyze security --offline=yes` must rate the unit's exposure 2.5 or less.
#   unit_files.sh networkd BUILD_DIR
#       runs systemd-networkd itself, in private network and mount namespaces, on the networkd
#       files; it must load them without a single complaint. A broken copy must be caught.
#   unit_files.sh --print-doc-commands    the commands docs/operations.md must show
set -euo pipefail
source "$(dirname "$0")/lib.sh"

max_exposure=2.5
commands() {
  local root='$PWD/'$build
  [[ $build == /* ]] && root=$build  # a build dir outside the source tree
  stage_install='DESTDIR="'$root'/stage" cmake --install '$build' --prefix /usr'
  security='systemd-analyze security --offline=yes systemd/cyber-planner.service'
}
if [[ ${1:-} == --print-doc-commands ]]; then
  build=build
  commands
  printf '%s\n' "$stage_install" "$security"
  exit 0
fi
[[ $# -ge 2 ]] || { echo "usage: $0 verify|security|networkd BUILD_DIR" >&2; exit 2; }
case_name=$1
system_setup "$2"
commands

verify() {
  local stage=$build_abs/stage units out
  rm -rf "$stage"
  run_shown "$stage_install"
  units=$stage/usr/lib/systemd/system
  [[ -f $units/cyber-planner.service ]] || fail "cmake --install put no cyber-planner.service in $units"
  # verify resolves the unit's dependencies (basic.target, network-online.target, ...) in the
  # root too: take them from this machine, ours untouched.
  cp -an /usr/lib/systemd/system/. "$units/"
  [[ -x $stage/usr/bin/cyber-plannerd ]] || fail "no executable $stage/usr/bin/cyber-plannerd after cmake --install"
  echo "+ systemd-analyze verify --root=$stage cyber-planner.service"
  out=$(systemd-analyze verify --root="$stage" cyber-planner.service 2>&1) || fail "systemd-analyze verify failed: $out"
  [[ -z $out ]] || fail "systemd-analyze verify complained: $out"
  echo "verify: systemd-analyze verify accepts cyber-planner.service"
}

security() {
  local out level
  echo "+ $security"
  out=$(eval "$security" 2>&1) || fail "systemd-analyze security failed: $out"
  echo "$out"
  level=$(sed -n 's/.*Overall exposure level for cyber-planner\.service: \([0-9][0-9.]*\) .*/\1/p' <<<"$out")
  [[ -n $level ]] || fail "no 'Overall exposure level' line in the output"
  awk -v l="$level" -v m="$max_exposure" 'BEGIN { exit !(l <= m) }' ||
    fail "exposure level $level is above $max_exposure"
  echo "security: exposure level $level (at most $max_exposure)"
}

# Runs systemd-networkd on the files in directory $1; prints its log.
networkd_log() {
  local dir=$1
  unshare --net --mount bash -c '
    set -e
    mount -t tmpfs tmpfs /run
    install -d -o systemd-network -g systemd-network /run/systemd/netif
    mount --bind "$1" /etc/systemd/network
    ip link set lo up
    SYSTEMD_LOG_LEVEL=debug SYSTEMD_LOG_TARGET=console SYSTEMD_LOG_COLOR=0 \
      /lib/systemd/systemd-networkd >/run/networkd.log 2>&1 &
    for _ in $(seq 200); do
      grep -q "Enumeration completed" /run/networkd.log && break
      sleep 0.05
    done
    kill $! || true
    wait $! || true
    cat /run/networkd.log
  ' networkd "$dir" || true
}

# Complaints about the files in /etc/systemd/network (networkd names the file and line).
complaints() { grep -E '^/etc/systemd/network/[^:]+:[0-9]+: ' <<<"$1" || true; }

networkd() {
  local work=$build_abs/system/networkd log
  [[ -x /lib/systemd/systemd-networkd ]] || fail "systemd-networkd missing (package systemd)"
  rm -rf "$work"
  mkdir -p "$work/shipped" "$work/broken"
  cp systemd/network/* "$work/shipped/"

  # The checker must see a mistake: a bad bit rate and an unknown key.
  cp systemd/network/* "$work/broken/"
  sed -i 's/^BitRate=1M$/BitRate=1Mbit/; s/^RestartSec=\(.*\)$/RestartSec=\1\nRestartAfterBusOff=yes/' \
    "$work/broken/80-cyber-can0.network"
  log=$(networkd_log "$work/broken")
  [[ $(complaints "$log" | wc -l) -ge 2 ]] || { echo "$log"; fail "networkd did not report the broken copy"; }

  log=$(networkd_log "$work/shipped")
  echo "$log" >"$work/networkd.log"
  grep -q 'Enumeration completed' <<<"$log" || { echo "$log"; fail "systemd-networkd did not start"; }
  grep -q 'vcan0: loaded "vcan"' <<<"$log" || { echo "$log"; fail "networkd did not load 80-cyber-vcan0.netdev"; }
  if [[ -n $(complaints "$log") ]]; then
    complaints "$log"
    fail "systemd-networkd complained about the shipped files"
  fi
  echo "networkd: systemd-networkd loads the shipped files without complaint (log: $work/networkd.log)"
}

case $case_name in
  verify) verify ;;
  security) security ;;
  networkd) networkd ;;
  *) echo "unit_files: unknown case '$case_name'" >&2; exit 2 ;;
esac
