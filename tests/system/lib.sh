# shellcheck shell=bash
# Shared by the system test scripts (tests/system/*.sh). Source it after setting -euo pipefail.
#   system_setup BUILD_DIR   cd to the source root; $build = the build dir, relative to the
#                            source root when inside it (so commands read as docs/operations.md
#                            shows them, with "build"); $build_abs = absolute
#   enter_netns "$0" ARGS    re-run the script in a private network namespace whose lo is up
#                            with the multicast route LCM needs: nothing leaves the namespace
#   run_shown CMD            print and run (eval) one command of docs/operations.md
#   docs_scratch             $work = a scratch folder (removed on exit) that sees the build as
#                            "build" and the configs as "config", where docs' commands run as shown
#   fail WHAT                print and exit 1

src=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)

fail() { echo "FAIL: $*" >&2; exit 1; }

system_setup() {
  build_abs=$(realpath -m "$1")
  cd "$src" || exit 2
  build=$(realpath -m --relative-base="$src" "$build_abs")
}

enter_netns() {
  if [[ ${CYBER_SYSTEM_NETNS:-} != 1 ]]; then
    local as_root=()
    [[ $(id -u) -eq 0 ]] || as_root=(--map-root-user)
    exec unshare --net "${as_root[@]}" env CYBER_SYSTEM_NETNS=1 "$@"
  fi
  ip link set lo up
  ip route add 224.0.0.0/4 dev lo
}

docs_scratch() {
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
  ln -s "$build_abs" "$work/build"
  ln -s "$src/config" "$work/config"
}

run_shown() {
  echo "+ $1"
  eval "$1"
}
