#!/usr/bin/env bash
# system.package: builds the Debian package with CPack, as docs/operations.md shows, checks its
# control data (dependencies that name installed packages, the conffile) and contents, unpacks
# it into a scratch root with dpkg -x and runs the packaged programs from there.
#   package.sh BUILD_DIR PROGRAM...   PROGRAM: each built program the package must hold; each
#                                     must answer --help with status 0
#   package.sh --print-doc-commands   the commands docs/operations.md must show
set -euo pipefail
source "$(dirname "$0")/lib.sh"

commands() {
  pack="cpack --config $build/CPackConfig.cmake -B $build/package"
  info="dpkg-deb --info $build/package/cyber-planner_*.deb"
  contents="dpkg-deb --contents $build/package/cyber-planner_*.deb"
  unpack="dpkg -x $build/package/cyber-planner_*.deb $build/package/root"
}
if [[ ${1:-} == --print-doc-commands ]]; then
  build=build
  commands
  printf '%s\n' "$pack" "$info" "$contents" "$unpack"
  exit 0
fi
[[ $# -ge 1 ]] || { echo "usage: $0 BUILD_DIR PROGRAM... | --print-doc-commands" >&2; exit 2; }
system_setup "$1"
shift
programs=("$@")
commands

rm -rf "$build/package"
run_shown "$pack"
debs=("$build"/package/cyber-planner_*.deb)
[[ ${#debs[@]} -eq 1 && -f ${debs[0]} ]] || fail "expected one cyber-planner_*.deb in $build/package"
deb=${debs[0]}

# Control data.
run_shown "$info" | tee "$build/package/info.txt"
field() { sed -n "s/^ $1: //p" "$build/package/info.txt"; }
[[ $(field Package) == cyber-planner ]] || fail "Package is not cyber-planner"
[[ $(field Architecture) == "$(dpkg --print-architecture)" ]] || fail "Architecture is not this machine's"
depends=$(field Depends)
[[ $depends == *libc6* && $depends == *libstdc++6* ]] || fail "Depends lacks libc6/libstdc++6: $depends"
# Each dependency names a real package (here: one that is installed, since the build used it).
IFS=',' read -ra alternatives <<<"$depends"
# Virtual packages the installed ones provide (libspdlog1.10 provides libspdlog1.10-fmt9). Read
# once into a variable: `grep -q` at the end of a pipeline exits at the first match, and under
# pipefail the SIGPIPE of the commands before it failed this check now and then.
provided=$(dpkg-query -W -f='${db:Status-Abbrev}|${Provides}\n' 2>/dev/null | sed -n 's/^ii *|//p' | tr ',' '\n' |
  sed -E 's/^ *//; s/ .*//')
for dependency in "${alternatives[@]}"; do
  name=$(sed -E 's/^ *//; s/[ (|].*//' <<<"$dependency")
  # This machine's architecture: with a foreign one added (tools/setup --arch arm64) a plain name
  # matches each architecture's package.
  status=$(dpkg-query -W -f='${Status}' "$name:$(dpkg --print-architecture)" 2>/dev/null ||
    dpkg-query -W -f='${Status}' "$name" 2>/dev/null || true)
  [[ $status == 'install ok installed' ]] || grep -qx -- "$name" <<<"$provided" ||
    fail "dependency '$name' is neither installed nor provided by an installed package"
done
for program in "${programs[@]}"; do
  case $program in
    cyber-plannerd) [[ $depends == *liblcm1* ]] || fail "cyber-plannerd links LCM but Depends lacks liblcm1" ;;
    cyber-plan) [[ $depends == *libcairo2* ]] || fail "cyber-plan links cairo but Depends lacks libcairo2" ;;
  esac
done
conffiles=$(dpkg-deb --ctrl-tarfile "$deb" | tar -xO ./conffiles)
[[ $conffiles == /etc/cyber-planner/robot.toml ]] || fail "conffiles is '$conffiles'"

# Contents.
run_shown "$contents" >"$build/package/contents.txt"
for path in ./etc/cyber-planner/robot.toml ./usr/lib/systemd/system/cyber-planner.service \
            ./usr/bin/cyber-lcm-spy ./usr/share/cyber-planner/network/80-cyber-can0.network \
            ./usr/share/cyber-planner/reefscape-2025.toml ./usr/share/doc/cyber-planner/README.md \
            "${programs[@]/#/./usr/bin/}"; do
  grep -q " $path\$" "$build/package/contents.txt" || fail "$path missing from the package"
done

# Unpacked into a scratch root: the programs run from there.
run_shown "$unpack"
root=$build/package/root
# The installed robot.toml is the default with the robot-LAN URL (ttl=1), and nothing else changed.
sed 's|^lcm_url = "udpm://239.255.76.67:5810?ttl=0"$|lcm_url = "udpm://239.255.76.67:5810?ttl=1"|' \
  config/reefscape-2025.toml >"$build/package/robot-lan.toml"
grep -q 'ttl=1"$' "$build/package/robot-lan.toml" || fail "config/reefscape-2025.toml has no ttl=0 lcm_url line"
cmp -s "$root/etc/cyber-planner/robot.toml" "$build/package/robot-lan.toml" ||
  fail "robot.toml is not the default with lcm_url ttl=1"
for program in "${programs[@]}"; do
  echo "+ $root/usr/bin/$program --help"
  out=$("$root/usr/bin/$program" --help 2>&1) || fail "$program --help exited with status $?: $out"
  grep -qi usage <<<"$out" || fail "$program --help printed no usage: $out"
done
[[ -f $root/usr/share/cyber-planner/java/cyber_lcmtypes.jar ]] || fail "the package holds no cyber_lcmtypes.jar"
classpath=$("$root/usr/bin/cyber-lcm-spy" --print-classpath)
[[ $classpath == "$(realpath "$root")/usr/share/cyber-planner/java/cyber_lcmtypes.jar:"* ]] ||
  fail "cyber-lcm-spy does not use the packaged jar: $classpath"
echo "package: $(basename "$deb") holds ${programs[*]:-no programs}; Depends: $depends"
