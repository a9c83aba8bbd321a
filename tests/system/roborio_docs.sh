#!/usr/bin/env bash
# system.roborio_docs: every command docs/roborio.md shows (its ```sh blocks) is run here, as
# written, from a scratch folder that sees the build as "build". Its Java examples are compiled
# from a copy of the Maven folder by system.roborio_vendordep_2026/_2027 (roborio_vendordep.sh).
#   roborio_docs.sh BUILD_DIR
set -euo pipefail
source "$(dirname "$0")/lib.sh"
system_setup "$1"
enter_netns "$0" "$@"  # the daemon's LCM stays in a private namespace
doc=$src/docs/roborio.md

# The page's commands, in order: a new one must be added here (and run below).
expected=(
  'cmake --build build --target cyber_roborio_maven'
  'mkdir -p "$ROBOT_PROJECT/cyber-planner" "$ROBOT_PROJECT/vendordeps"'
  'cp -r build/roborio/publish/maven "$ROBOT_PROJECT/cyber-planner/"'
  'cp build/roborio/publish/CyberPlanner-2027.json "$ROBOT_PROJECT/vendordeps/"'
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

# 1. The Maven folder and the vendordeps.
run_shown "${expected[0]}"
for f in CyberPlanner-2026.json CyberPlanner-2027.json maven/lcm/lcm/1.3.1/lcm-1.3.1.jar; do
  [[ -f build/roborio/publish/$f ]] || fail "build/roborio/publish/$f missing"
done
for a in cyber-planner-core cyber-planner-wpilib2026 cyber-planner-wpilib2027 cyber-lcmtypes; do
  for kind in .jar -sources.jar -javadoc.jar .pom; do
    compgen -G "build/roborio/publish/maven/org/cyberplanner/$a/*/$a-*$kind" >/dev/null || fail "no $a $kind"
  done
done

# 2. Into a robot project; the JSON's relative mavenUrls entry resolves there.
ROBOT_PROJECT=$work/robot
run_shown "${expected[1]}"
run_shown "${expected[2]}"
run_shown "${expected[3]}"
python3 - "$ROBOT_PROJECT" <<'PY' || fail "the vendordep does not resolve in the robot project"
import json, os, sys
root = sys.argv[1]
dep = json.load(open(os.path.join(root, "vendordeps", "CyberPlanner-2027.json")))
assert dep["wpilibYear"].startswith("2027"), dep
(url,) = dep["mavenUrls"]
for j in dep["javaDependencies"]:
    path = os.path.join(root, url, *j["groupId"].split("."), j["artifactId"], j["version"],
                        f'{j["artifactId"]}-{j["version"]}.jar')
    assert os.path.isfile(path), path
print(f'vendordep: {len(dep["javaDependencies"])} java dependencies resolve in {url}')
PY

# 3. Desktop simulation: the config, then the daemon until it publishes its status, then SIGTERM.
run_shown "${expected[4]}"
grep -qx 'setpoint_echo_full_rate = true  # true: ARM_SETPOINT every stream tick (desktop simulation)' build/sim.toml ||
  fail "build/sim.toml does not turn setpoint_echo_full_rate on"
echo "+ ${expected[5]} &"
(eval "exec ${expected[5]}") >"$work/daemon.log" 2>&1 &
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

echo "roborio_docs: ${#expected[@]} commands run"
