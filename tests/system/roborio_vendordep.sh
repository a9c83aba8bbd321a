#!/usr/bin/env bash
# system.roborio_vendordep_YEAR: the vendordep's year value (for 2027 the build's wpilibYear, and
# what write_vendordep.cmake writes by default and for an override), and a robot project that has
# only a copy of the Maven folder and the vendordep of one WPILib year (docs/roborio.md,
# "Installing"), no CMake build tree: every javaDependency resolves through the JSON's relative
# mavenUrls entry (with its pom, and for our artifacts its -sources and -javadoc jars), and that
# year's example of the page compiles with plain javac against those jars and the vendors'
# stand-ins alone, as bytecode 17, and so does the page's Pose example.
#   roborio_vendordep.sh BUILD_DIR YEAR STANDINS_JAR
set -euo pipefail
build=$1 year=$2 standins=$3
src=$(cd "$(dirname "$0")/../.." && pwd)
fail() { echo "FAIL: $*"; exit 1; }
publish=$build/roborio/publish
[[ -f $publish/CyberPlanner-$year.json ]] || fail "$publish/CyberPlanner-$year.json missing: build the cyber_roborio_maven target"
[[ -f $standins ]] || fail "$standins missing"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
project=$work/robot
mkdir -p "$project/cyber-planner" "$project/vendordeps"
cp -r "$publish/maven" "$project/cyber-planner/"
cp "$publish/CyberPlanner-$year.json" "$project/vendordeps/"
cp "$standins" "$work/standins.jar"

# The year value GradleRIO checks: 2026's frcYear is "2026"; 2027's wpilibYear is the build's
# CYBER_WPILIB_YEAR_2027, by default the one GradleRIO's 2027 line expects (2027_alpha5, as
# docs/roborio.md says), and any other the build names (docs/roborio.md, "Installing").
if [[ $year == 2026 ]]; then
  key=frcYear expected=2026
else
  key=wpilibYear
  expected=$(sed -n 's/^CYBER_WPILIB_YEAR_2027:STRING=//p' "$build/CMakeCache.txt")
  [[ -n $expected ]] || fail "no CYBER_WPILIB_YEAR_2027 in $build/CMakeCache.txt"
  default=$(sed -n 's/^set(CYBER_WPILIB_YEAR_2027_DEFAULT \(.*\))$/\1/p' "$src/roborio/src/wpilib/wpilib_year_2027.cmake")
  [[ $default == 2027_alpha5 ]] || fail "the default wpilibYear is '$default', docs/roborio.md says 2027_alpha5"
  grep -q '"wpilibYear": "2027_alpha5"' "$src/docs/roborio.md" || fail "docs/roborio.md does not name the default wpilibYear"
  version=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["version"])' "$publish/CyberPlanner-2027.json")
  written() {  # written [-DCYBER_WPILIB_YEAR_2027=...]: the wpilibYear write_vendordep.cmake writes
    rm -f "$work/CyberPlanner-2027.json"
    cmake -DSOURCE_DIR="$src/roborio" -DPUBLISH_DIR="$work" -DVERSION="$version" -DYEAR=2027 "$@" \
      -P "$src/roborio/write_vendordep.cmake" >"$work/cmake.log" 2>&1 || { cat "$work/cmake.log"; return 1; }
    python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["wpilibYear"])' "$work/CyberPlanner-2027.json"
  }
  [[ $(written) == 2027_alpha5 ]] || fail "without CYBER_WPILIB_YEAR_2027 the 2027 vendordep's wpilibYear is not 2027_alpha5"
  [[ $(written -DCYBER_WPILIB_YEAR_2027=2027_alpha7) == 2027_alpha7 ]] ||
    fail "-DCYBER_WPILIB_YEAR_2027=2027_alpha7 does not make the 2027 vendordep's wpilibYear 2027_alpha7"
  if written -DCYBER_WPILIB_YEAR_2027=2027-alpha7 >/dev/null; then fail "wpilibYear 2027-alpha7 was accepted"; fi
  grep -q "is not a WPILib 2027 year" "$work/cmake.log" || fail "wpilibYear 2027-alpha7 was refused without saying why"
  echo "vendordep 2027: wpilibYear 2027_alpha5 by default, 2027_alpha7 when the build names it, 2027-alpha7 refused"
fi

# Resolve as GradleRIO does: a relative mavenUrls entry is a folder of the robot project.
classpath=$(cd "$project" && python3 - "vendordeps/CyberPlanner-$year.json" "$year" "$key" "$expected" <<'PY'
import json, os, sys
dep = json.load(open(sys.argv[1]))
year, key, expected = sys.argv[2:5]
assert dep.get(key) == expected, (key, dep.get(key), expected)
assert [r["uuid"] for r in dep["requires"]] == ["111e20f7-815e-48f8-9dd6-e675ce75b266"], dep["requires"]
(url,) = dep["mavenUrls"]
assert "://" not in url and not os.path.isabs(url), url
jars = []
for j in dep["javaDependencies"]:
    base = os.path.join(url, *j["groupId"].split("."), j["artifactId"], j["version"], f'{j["artifactId"]}-{j["version"]}')
    for suffix in [".jar", ".pom"] + (["-sources.jar", "-javadoc.jar"] if j["groupId"] == "org.cyberplanner" else []):
        assert os.path.isfile(base + suffix), base + suffix
    jars.append(os.path.abspath(base + ".jar"))
assert any(j.endswith(f"cyber-planner-wpilib{year}-" + dep["version"] + ".jar") for j in jars), jars
print(":".join(jars))
PY
) || fail "the $year vendordep does not resolve in the copied Maven folder"
echo "vendordep $year: $(tr ':' '\n' <<<"$classpath" | wc -l) jars resolve in cyber-planner/maven"

# The page's Java examples: the first is 2026, the second 2027.
index=$([[ $year == 2026 ]] && echo 1 || echo 2)
awk -v want="$index" '$0 == "```java" { n++; inside = (n == want); next } /^```/ { inside = 0 } inside' \
  "$src/docs/roborio.md" >"$work/CyberArm.java"
lines=$(grep -cv '^\(import \|$\)' "$work/CyberArm.java")
[[ $lines -ge 5 && $lines -le 20 ]] || fail "the $year example has $lines lines besides imports, the page says about 20"
echo "+ javac CyberArm.java ($year, $lines lines besides imports)"
javac --release 17 -Xlint:all -Werror -d "$work/classes" -cp "$classpath:$work/standins.jar" "$work/CyberArm.java" ||
  fail "the $year example of docs/roborio.md does not compile against the vendordep's jars"
major=$(javap -v -cp "$work/classes" CyberArm | sed -n 's/.*major version: //p')
[[ $major == 61 ]] || fail "class file major version $major, expected 61 (Java 17)"

# The page's third Java block, a Pose built by joint index with pieces and a scene (statements of
# the core's API), compiles in a method body against the same jars.
{
  echo 'import cyberplanner.roborio.*;'
  echo 'final class PoseSnippet {'
  echo '  void snippet() {'
  awk '$0 == "```java" { n++; inside = (n == 3); next } /^```/ { inside = 0 } inside' "$src/docs/roborio.md"
  echo '  }'
  echo '}'
} >"$work/PoseSnippet.java"
grep -q 'Pose' "$work/PoseSnippet.java" || fail "docs/roborio.md has no third Java block with a Pose"
echo "+ javac PoseSnippet.java (the page's Pose example)"
javac --release 17 -Xlint:all -Werror -d "$work/classes" -cp "$classpath" "$work/PoseSnippet.java" ||
  fail "the Pose example of docs/roborio.md does not compile against the vendordep's jars"
echo "roborio_vendordep $year: PASS"
