#!/usr/bin/env python3
"""Fails when the planner's shape breaks one of its rules (tests/unit/planner/README.md).

Usage: check_planner_layout.py ROOT

  - the public include folder (planner/include) holds at most 8 headers;
  - every source file of planner/src has its test: the same path under tests/unit/planner, with
    _test added to its name;
  - outside the planner, its tests (tests/unit/planner, tests/support) and its benchmarks
    (tests/bench), code includes only the umbrella header cyber/planner.hpp of the planner;
  - a public header includes no private one.
Prints one line per broken rule; exits 1 if there is any.
"""
import os
import re
import subprocess
import sys

MAX_PUBLIC_HEADERS = 8
INTERNAL = ("planner/", "tests/unit/planner/", "tests/support/", "tests/bench/")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.MULTILINE)


def tracked(root, *patterns):
    out = subprocess.run(["git", "-C", root, "ls-files", "--cached", "--others", "--exclude-standard", *patterns],
                         capture_output=True, text=True, check=True).stdout.split()
    return [f for f in out if os.path.exists(os.path.join(root, f))]


def main(root):
    problems = []
    public = [f for f in tracked(root, "planner/include") if f.endswith(".hpp")]
    if len(public) > MAX_PUBLIC_HEADERS:
        problems.append(f"planner/include holds {len(public)} headers, more than {MAX_PUBLIC_HEADERS}: {public}")
    private = {os.path.relpath(f, "planner/src") for f in tracked(root, "planner/src") if f.endswith(".hpp")}
    for f in public:
        for target in INCLUDE.findall(open(os.path.join(root, f)).read()):
            if target in private:
                problems.append(f"{f}: the public header includes the private {target}")
    for f in tracked(root, "planner/src"):
        if not f.endswith(".cpp"):
            continue
        test = "tests/unit/planner/" + os.path.relpath(f, "planner/src")[: -len(".cpp")] + "_test.cpp"
        if not os.path.exists(os.path.join(root, test)):
            problems.append(f"{f} has no test {test}")
    for f in tracked(root, "*.cpp", "*.hpp", "*.h", "*.cpp.in"):
        if f.startswith(INTERNAL) or f.startswith("core/"):
            continue
        for target in INCLUDE.findall(open(os.path.join(root, f), errors="replace").read()):
            if (target.startswith("cyber/planner/") or target in private) and target != "cyber/planner.hpp":
                problems.append(f"{f}: includes {target}; outside the planner, include cyber/planner.hpp")
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
