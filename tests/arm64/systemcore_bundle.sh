#!/usr/bin/env bash
# arm64.systemcore_bundle: the Systemcore package that tools/package --arch arm64 wrote
# (tools/systemcore-ipk) as docs/operations.md ("Systemcore") shows it. Its archive and control
# data; the same cyber-plannerd and cyber-plan as the arm64 Debian package's (equal build IDs);
# every library they need either bundled or one of what the target provides (Debian's arm64
# libc6, libstdc++6, libgcc-s1), with no symbol version newer than Systemcore's glibc and
# libstdc++ and every segment aligned for its 16 KiB pages. Then the bundle runs under
# qemu-aarch64 in a root holding only those three packages and the bundle (chroot: no fallback to
# this machine's arm64 libraries), in a private network namespace: cyber-plan plans a public move
# with the Systemcore configuration as the native cyber-plan does, and cyber-plannerd --can none
# starts, publishes ARM_DAEMON_STATUS over the loopback route with ttl=0 and exits 0 on SIGTERM.
#   systemcore_bundle.sh BUILD_DIR NATIVE_CYBER_PLAN
#   systemcore_bundle.sh --print-doc-commands   the commands docs/operations.md must show
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../system/lib.sh"

commands() {
  ipk="$build/package/cyber-planner_*_aarch64.ipk"
  root="$build/package/bare-root"
  members="ar t $ipk"
  control="ar p $ipk control.tar.gz | tar -xzO ./control"
  contents="ar p $ipk data.tar.gz | tar -tzv"
  plan="chroot $root /qemu-aarch64-static /usr/bin/cyber-plan --config /etc/cyber-planner/robot.toml --from 0.20,1.57 --to 1.97,5.17 --json"
  daemon="chroot $root /qemu-aarch64-static /usr/bin/cyber-plannerd --config /etc/cyber-planner/robot.toml --can none"
}
if [[ ${1:-} == --print-doc-commands ]]; then
  build='build-arm64'
  commands
  printf '%s\n' "$members" "$control" "$contents" "$plan" "$daemon"
  exit 0
fi
[[ $# -eq 2 ]] || { echo "usage: $0 BUILD_DIR NATIVE_CYBER_PLAN | --print-doc-commands" >&2; exit 2; }
native_plan=$(realpath "$2")
[[ -x $native_plan ]] || fail "no native cyber-plan at $2 (tools/package --arch arm64 --test builds it)"
system_setup "$1"
enter_netns "$0" "$@"
commands

# Systemcore's C library and C++ runtime: glibc 2.42 and libstdc++ of GCC 14.3.0 (Buildroot
# 2025.11.3, docs/operations.md, "Systemcore"). Its kernel uses 16 KiB pages.
target_glibc=2.42 target_glibcxx=3.4.33 target_cxxabi=1.3.15 page_bytes=$((16 * 1024))
# The libraries of its toolchain that Buildroot installs there (GLIBC_LIBS_LIB of
# package/glibc/glibc.mk at 2025.11.3, and libstdc++, which WPILib's C++ robot programs link):
# fewer than Debian's libc6 has (no libnsl, libBrokenLocale, ...), so a need outside this list would
# run in the bare root here and fail on the controller.
target_sonames='^(ld-linux-aarch64\.so\.1|libanl\.so\.1|libc\.so\.6|libdl\.so\.2|libgcc_s\.so\.1|libm\.so\.6|libpthread\.so\.0|libresolv\.so\.2|librt\.so\.1|libutil\.so\.1|libmvec\.so\.1|libnss_(files|dns)\.so\.2|libstdc\+\+\.so\.6)$'
programs=(cyber-plannerd cyber-plan)

ipks=("$build"/package/cyber-planner_*_aarch64.ipk)
debs=("$build"/package/cyber-planner_*_arm64.deb)
[[ ${#ipks[@]} -eq 1 && -f ${ipks[0]} ]] || fail "expected one cyber-planner_*_aarch64.ipk in $build/package (tools/package --arch arm64)"
[[ ${#debs[@]} -eq 1 && -f ${debs[0]} ]] || fail "expected one cyber-planner_*_arm64.deb in $build/package"
work=$build_abs/package/systemcore-test
rm -rf "$work" "$root"
mkdir -p "$work"

# The archive and its control data.
out=$(run_shown "$members")
[[ $(tail -n +2 <<<"$out" | tr '\n' ' ') == 'debian-binary control.tar.gz data.tar.gz ' ]] ||
  fail "the .ipk's members are not debian-binary, control.tar.gz, data.tar.gz"
run_shown "$control" | tee "$work/control"
field() { sed -n "s/^$1: //p" "$work/control"; }
[[ $(field Package) == cyber-planner ]] || fail "Package is '$(field Package)'"
[[ $(field Architecture) == aarch64 ]] || fail "Architecture is '$(field Architecture)'"
[[ $(field Version) == "$(dpkg-deb -f "${debs[0]}" Version)" ]] || fail "Version differs from the .deb's"
[[ -z $(field Depends) ]] || fail "the .ipk depends on packages Systemcore does not have: $(field Depends)"
[[ $(field X-Auto-Start) == false ]] || fail "X-Auto-Start is not false: installing must not start the planner"
[[ $(ar p "${ipks[0]}" control.tar.gz | tar -xzO ./conffiles) == /etc/cyber-planner/robot.toml ]] ||
  fail "conffiles is not /etc/cyber-planner/robot.toml"
run_shown "$contents" >"$work/contents"
for path in ./usr/bin/cyber-plannerd ./usr/bin/cyber-plan ./etc/cyber-planner/robot.toml \
            ./usr/lib/systemd/system/cyber-planner.service \
            ./usr/lib/systemd/system/cyber-planner.service.d/10-systemcore.conf \
            ./usr/share/doc/cyber-planner/operations.md; do
  grep -q " $path\$" "$work/contents" || fail "$path missing from the .ipk"
done

# The root: the files dpkg installed for libc6, libstdc++6 and libgcc-s1 (arm64), as they are on
# this machine (no download), the bundle, and the emulator (a static program of this machine).
# Merged /usr, as on Debian 12 and on Systemcore (systemd needs it of Buildroot).
mkdir -p "$root/usr/lib" "$root/usr/bin" "$root/usr/sbin"
for top in lib bin sbin; do ln -s "usr/$top" "$root/$top"; done
dpkg -L libc6:arm64 libstdc++6:arm64 libgcc-s1:arm64 | while IFS= read -r path; do
  [[ -d $path ]] && continue
  [[ -L $path || -f $path ]] || continue
  mkdir -p "$root$(dirname "$path")"
  cp -a "$path" "$root$path"
done
ar p "${ipks[0]}" data.tar.gz | tar -xzf - -C "$root"
cp /usr/bin/qemu-aarch64-static "$root/qemu-aarch64-static"

# The same programs as the Debian package's.
dpkg-deb -x "${debs[0]}" "$work/deb"
build_id() { readelf -n "$1" | sed -n 's/^ *Build ID: //p'; }
for program in "${programs[@]}"; do
  id=$(build_id "$root/usr/bin/$program")
  [[ -n $id && $id == "$(build_id "$work/deb/usr/bin/$program")" ]] ||
    fail "$program of the .ipk is not the .deb's (build ID '$id')"
done

# Every ELF file of the bundle: AArch64, its libraries found in the bundle or the root, no symbol
# version newer than the target's, every loadable segment aligned to at least a 16 KiB page.
newest() { sed -n "s/.*Name: $1_\([0-9][0-9.]*\).*/\1/p" | sort -V | tail -n1; }
not_newer() { [[ -z $1 || $(printf '%s\n%s\n' "$1" "$2" | sort -V | tail -n1) == "$2" ]]; }
mapfile -t elves < <(find "$root/usr/bin" "$root/usr/lib/cyber-planner" -type f)
bundled=$(find "$root/usr/lib/cyber-planner" -type f | wc -l)
all_versions=''
for elf in "${elves[@]}"; do
  name=${elf#"$root"}
  [[ $(readelf -h "$elf" | sed -n 's/^ *Machine: *//p') == AArch64 ]] || fail "$name is not AArch64"
  for soname in $(readelf -d "$elf" | sed -n 's/.*(NEEDED).*\[\(.*\)\]$/\1/p'); do
    [[ -e $root/usr/lib/cyber-planner/$soname ]] && continue
    [[ -e $root/lib/aarch64-linux-gnu/$soname || -e $root/usr/lib/aarch64-linux-gnu/$soname ]] ||
      fail "$name needs $soname, which is neither bundled nor in the root"
    grep -qE "$target_sonames" <<<"$soname" || fail "$name needs $soname, which Systemcore's Buildroot does not install"
  done
  all_versions+=$(readelf -V --wide "$elf")$'\n'
  while read -r align; do
    ((align >= page_bytes)) || fail "$name has a loadable segment aligned to $align bytes (< $page_bytes)"
  done < <(readelf -lW "$elf" | awk '$1 == "LOAD" { print $NF }')
done
glibc=$(newest GLIBC <<<"$all_versions")
glibcxx=$(newest GLIBCXX <<<"$all_versions")
cxxabi=$(newest CXXABI <<<"$all_versions")
not_newer "$glibc" "$target_glibc" || fail "the bundle needs GLIBC_$glibc; Systemcore has $target_glibc"
not_newer "$glibcxx" "$target_glibcxx" || fail "the bundle needs GLIBCXX_$glibcxx; Systemcore has $target_glibcxx"
not_newer "$cxxabi" "$target_cxxabi" || fail "the bundle needs CXXABI_$cxxabi; Systemcore has $target_cxxabi"
for program in "${programs[@]}"; do
  rpath=$(readelf -d "$root/usr/bin/$program" | sed -n 's/.*(RPATH).*\[\(.*\)\]$/\1/p')
  [[ $rpath == "\$ORIGIN/../lib/cyber-planner" ]] || fail "$program's RPATH is '$rpath'"
done
echo "bundle: ${#elves[@]} AArch64 files ($bundled bundled libraries); newest versions needed GLIBC_$glibc," \
     "GLIBCXX_$glibcxx, CXXABI_$cxxabi (Systemcore: $target_glibc, $target_glibcxx, $target_cxxabi)"

# The configuration: the reference robot with the four Systemcore settings, nothing else changed.
config=$root/etc/cyber-planner/robot.toml
for setting in 'lcm_url = "udpm://239.255.76.67:5810?ttl=0"' 'can_interface = "can_s0"' 'setpoint_echo_full_rate = true' \
    'robot_controller = "systemcore"'; do
  grep -qF "$setting  #" "$config" || fail "robot.toml lacks '$setting'"
done
changed=$(diff config/reefscape-2025.toml "$config" | grep -c '^>' || true)
[[ $changed -eq 4 ]] || fail "robot.toml differs from config/reefscape-2025.toml in $changed lines, expected 4"

# The unit and its drop-in, as systemd reads them (the units they name taken from this machine,
# ip for ExecStartPre).
verify_root=$work/verify-root
mkdir -p "$verify_root/sbin"
cp -a "$root/usr" "$verify_root/"
cp -an /usr/lib/systemd/system/. "$verify_root/usr/lib/systemd/system/"
cp "$(command -v ip)" "$verify_root/sbin/ip"
out=$(systemd-analyze verify --root="$verify_root" cyber-planner.service 2>&1) || fail "systemd-analyze verify failed: $out"
[[ -z $out ]] || fail "systemd-analyze verify complained: $out"
echo "unit: systemd-analyze verify accepts cyber-planner.service with 10-systemcore.conf"

# One public move in the bare root, as the native cyber-plan plans it.
out=$(run_shown "$plan") || fail "cyber-plan in the bare root exited with status $?: $out"
native=$("$native_plan" --config "$config" --from 0.20,1.57 --to 1.97,5.17 --json) || fail "native cyber-plan failed: $native"
python3 - "${out#*$'\n'}" "$native" <<'PY' || fail "cyber-plan in the bare root: $out; native: $native"
import json, sys
arm64, native = json.loads(sys.argv[1]), json.loads(sys.argv[2])
assert arm64['status'] == native['status'] == 'ok', (arm64, native)
relative = abs(arm64['duration_s'] - native['duration_s']) / native['duration_s']
print('cyber-plan STOW->L4 in the bare root: %.9f s (native %.9f s, relative difference %.1e), '
      'planned in %.1f ms under emulation' % (arm64['duration_s'], native['duration_s'], relative, arm64['total_ms']))
assert relative <= 1e-6, relative
PY

# The daemon in the bare root: ARM_DAEMON_STATUS on the loopback route, then a clean SIGTERM.
url=$(sed -n 's/^lcm_url = "\([^"]*\)".*/\1/p' "$config")
rm -f "$work/listening"
python3 "$here/lcm_channel_listener.py" "$url" ARM_DAEMON_STATUS 120 "$work/listening" >"$work/listener.out" 2>&1 &
listener=$!
for _ in $(seq 100); do [[ -e $work/listening ]] && break; sleep 0.1; done
[[ -e $work/listening ]] || fail "the LCM listener did not start: $(cat "$work/listener.out")"
echo "+ $daemon"
# exec: the job's process is chroot's and then the emulator's, which passes SIGTERM to the daemon.
eval "exec $daemon" >"$work/daemon.log" 2>&1 &
daemon_pid=$!
trap 'kill "$daemon_pid" "$listener" 2>/dev/null || true' EXIT
wait "$listener" || fail "$(cat "$work/listener.out"); daemon log: $(tail -n 20 "$work/daemon.log")"
cat "$work/listener.out"
kill -0 "$daemon_pid" 2>/dev/null || fail "cyber-plannerd exited early: $(tail -n 20 "$work/daemon.log")"
kill -TERM "$daemon_pid"
stopped_at=$SECONDS
for _ in $(seq 300); do kill -0 "$daemon_pid" 2>/dev/null || break; sleep 0.1; done
kill -0 "$daemon_pid" 2>/dev/null && fail "cyber-plannerd still runs 30 s after SIGTERM"
status=0
wait "$daemon_pid" || status=$?
[[ $status -eq 0 ]] || fail "cyber-plannerd exited with status $status after SIGTERM: $(tail -n 20 "$work/daemon.log")"
echo "cyber-plannerd (bare root, emulated): ARM_DAEMON_STATUS published, exit 0 $((SECONDS - stopped_at)) s after SIGTERM"
echo "systemcore bundle: $(basename "${ipks[0]}") runs with only libc6, libstdc++6 and libgcc-s1 under it"
