#!/usr/bin/env bash
# system.roborio_docs: every command docs/roborio.md shows (its ```sh blocks) is run here, as
# written, from a scratch folder that sees the build as "build"; and its Java example ("A subsystem
# in 20 lines") is compiled against the library and the stand-ins.
#   roborio_docs.sh BUILD_DIR
set -euo pipefail
source "$(dirname "$0")/lib.sh"
system_setup "$1"
enter_netns "$0" "$@"  # the daemon's LCM stays in a private namespace
doc=$src/docs/roborio.md

# The page's commands, in order: a new one must be added here (and run below).
expected=(
  'cmake --build build --target cyber_roborio_maven'
  'cp build/roborio/CyberPlanner.json "$ROBOT_PROJECT/vendordeps/"'
  "sed 's/^setpoint_echo_full_rate = false/setpoint_echo_full_rate = true/' config/reefscape-2025.toml > build/sim.toml"
  'build/daemon/app/cyber-plannerd --config build/sim.toml --can none'
)
block() {  # block LANG: the lines of the page's ```LANG blocks
  awk -v open='```'"$1" '$0 == open { inside = 1; next } /^```/ { inside = 0 } inside' "$doc"
}
mapfile -t shown < <(block sh)
[[ ${#shown[@]} -eq ${#expected[@]} ]] || fail "docs/roborio.md shows ${#shown[@]} commands, this test runs ${#expected[@]}"
for i in "${!expected[@]}"; do
  [[ ${shown[$i]} == "${expected[$i]}" ]] || fail "docs/roborio.md command $((i + 1)) is '${shown[$i]}', expected '${expected[$i]}'"
done

work=$(mktemp -d)
daemon_pid=
cleanup() {
  if [[ -n $daemon_pid ]]; then kill "$daemon_pid" 2>/dev/null || true; fi
  rm -rf "$work"
}
trap cleanup EXIT
mkdir "$work/scratch"
ln -s "$build_abs" "$work/scratch/build"
ln -s "$src/config" "$work/scratch/config"
cd "$work/scratch"

# 1. The local Maven folder and the vendordep.
run_shown "${expected[0]}"
for jar in org/cyberplanner/cyber-roborio/*/cyber-roborio-*.jar org/cyberplanner/cyber-lcmtypes/*/cyber-lcmtypes-*.jar \
           lcm/lcm/1.3.1/lcm-1.3.1.jar; do
  compgen -G "build/roborio/maven/$jar" >/dev/null || fail "build/roborio/maven/$jar missing"
done

# 2. Into a robot project; every javaDependency of the JSON resolves in its Maven folder.
ROBOT_PROJECT=$work/robot
mkdir -p "$ROBOT_PROJECT/vendordeps"
run_shown "${expected[1]}"
python3 - "$ROBOT_PROJECT/vendordeps/CyberPlanner.json" <<'PY' || fail "the vendordep does not resolve"
import json, os, sys
dep = json.load(open(sys.argv[1]))
assert dep["frcYear"] == "2025", dep["frcYear"]
(url,) = dep["mavenUrls"]
assert url.startswith("file://"), url
root = url[len("file://"):]
for j in dep["javaDependencies"]:
    path = os.path.join(root, *j["groupId"].split("."), j["artifactId"], j["version"],
                        f'{j["artifactId"]}-{j["version"]}.jar')
    assert os.path.isfile(path), path
    assert os.path.isfile(path[:-4] + ".pom"), path
print(f'vendordep: {len(dep["javaDependencies"])} java dependencies resolve in {root}')
PY

# 3. Desktop simulation: the config, then the daemon until it publishes its status, then SIGTERM.
run_shown "${expected[2]}"
grep -qx 'setpoint_echo_full_rate = true  # true: ARM_SETPOINT every stream tick (desktop simulation)' build/sim.toml ||
  fail "build/sim.toml does not turn setpoint_echo_full_rate on"
echo "+ ${expected[3]} &"
(eval "exec ${expected[3]}") >"$work/daemon.log" 2>&1 &
daemon_pid=$!
status=
for _ in $(seq 1 600); do
  kill -0 "$daemon_pid" 2>/dev/null || { cat "$work/daemon.log"; fail "the daemon exited"; }
  if status=$(build/tests/integration/cyber-test-peer status --timeout 0.5 2>/dev/null); then break; fi
  sleep 0.1
done
grep -q '^mode=' <<<"$status" || fail "no ARM_DAEMON_STATUS from the simulation daemon within 60 s"
kill -TERM "$daemon_pid"
rc=0
wait "$daemon_pid" || rc=$?
daemon_pid=
[[ $rc -eq 0 ]] || { cat "$work/daemon.log"; fail "the daemon exited $rc after SIGTERM"; }
grep -q "CAN none" "$work/daemon.log" || fail "the daemon did not run with --can none"

# 4. The Java example compiles against the library (and the stand-ins of the vendor classes).
mkdir "$work/java"
block java >"$work/java/CyberArm.java"
lines=$(grep -cv '^\(import \|$\)' "$work/java/CyberArm.java")
[[ $lines -le 20 ]] || fail "the subsystem example has $lines lines, the page says 20"
echo "+ javac CyberArm.java ($lines lines besides imports)"
javac --release 17 -Xlint:all -Werror -d "$work/java" \
  -cp "build/roborio/cyber_roborio.jar:build/roborio/cyber_roborio_standins.jar:build/lcmtypes/cyber_lcmtypes.jar:/usr/share/java/lcm.jar" \
  "$work/java/CyberArm.java" || fail "the example of docs/roborio.md does not compile"
echo "roborio_docs: ${#expected[@]} commands run, the example compiles"
