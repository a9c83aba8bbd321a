#!/usr/bin/env python3
"""Fails when a floating-point literal other than 0, 1, 2 or 0.5 appears in planner/src outside a
named constant of the allow-list.

Usage: check_planner_literals.py ROOT [ALLOW_LIST]

Every tuned number of the planner lives in PlannerSettings (planner/include/cyber/planner/
planner_settings.hpp), with its reason, or is derived from the robot description. What is left in
planner/src are tolerances of floating-point arithmetic, facts of the method and unit conversions:
each is a named constexpr whose name the allow-list (planner_literals_allowed.txt beside this
script, one `FILE:NAME  # why` a line) holds. So a literal is accepted only inside the initialiser
of a constexpr that the list names in that file, and the list cannot rot: an entry whose constant
is gone, or whose constant holds no such literal any more, fails too, as does one without a why.

Comments, string and character literals are skipped. A floating-point literal is a number with a
decimal point or a decimal exponent (1.5, .5, 1e-9, 2.0f, 1e3, 8.0); integers are not judged.
Prints one line per problem; exits 1 if there is any.
"""
import os
import re
import subprocess
import sys

PLAIN = {0.0, 1.0, 2.0, 0.5}

# One alternation scanned left to right, so that a quote inside a comment or a digit separator
# inside a number (1'000) is not taken for the start of a literal.
TOKEN = re.compile(
    r"""(?P<comment>//[^\n]*|/\*.*?\*/)"""
    r"""|(?P<raw>R"(?P<delim>[^()\\\s]{0,16})\(.*?\)(?P=delim)")"""
    r"""|(?P<string>"(?:\\.|[^"\\\n])*")"""
    r"""|(?P<char>'(?:\\.|[^'\\\n])+')"""
    r"""|(?P<number>\.?\d(?:[eEpP][+-]|[\w.']|(?<=\w)'(?=\w))*)"""
    r"""|(?P<word>[A-Za-z_]\w*)""",
    re.DOTALL,
)
CONSTEXPR = re.compile(r"\bconstexpr\b(?P<type>[^;{}()=]*?)\b(?P<name>[A-Za-z_]\w*)\s*(?P<open>=|\{)")


def strip(text):
    """The source with comments, strings and character literals blanked, and its numbers."""
    out = []
    numbers = []
    last = 0
    for m in TOKEN.finditer(text):
        kind = "raw" if m.group("raw") is not None else m.lastgroup
        out.append(text[last:m.start()])
        if kind in ("comment", "raw", "string", "char"):
            out.append(re.sub(r"[^\n]", " ", m.group(0)))
        else:
            out.append(m.group(0))
            if kind == "number":
                numbers.append((m.start(), m.group(0)))
        last = m.end()
    out.append(text[last:])
    return "".join(out), numbers


def floating_value(token):
    """The value of a floating-point literal, or None for an integer (or a hex integer)."""
    t = token.replace("'", "")
    if t[:2] in ("0x", "0X"):
        if "p" not in t and "P" not in t:
            return None
        return float.fromhex(t.rstrip("fFlL"))
    if "." not in t and "e" not in t and "E" not in t:
        return None
    return float(t.rstrip("fFlL"))


def statement_end(code, start):
    """Where the declaration that starts at start ends: after its ';' at brace depth 0."""
    depth = 0
    i = start
    while i < len(code):
        c = code[i]
        if c in "({[":
            depth += 1
        elif c in ")}]":
            depth -= 1
            if depth < 0:
                return i
        elif c == ";" and depth == 0:
            return i + 1
        i += 1
    return len(code)


def constants(code):
    """Each constexpr variable's name and the span of its initialiser."""
    found = []
    for m in CONSTEXPR.finditer(code):
        found.append((m.group("name"), m.start("open"), statement_end(code, m.start("open"))))
    return found


def read_allow_list(path, problems):
    allowed = {}
    for number, line in enumerate(open(path), 1):
        entry, _, why = line.partition("#")
        entry = entry.strip()
        if not entry:
            continue
        if not why.strip():
            problems.append(f"{path}:{number}: {entry} says no why (`FILE:NAME  # why`)")
        file, _, name = entry.partition(":")
        if not name:
            problems.append(f"{path}:{number}: {entry} is not FILE:NAME")
            continue
        allowed.setdefault(file, {})[name] = number
    return allowed


def main(root, allow_path):
    problems = []
    allowed = read_allow_list(allow_path, problems)
    files = subprocess.run(["git", "-C", root, "ls-files", "--cached", "--others", "--exclude-standard", "planner/src"],
                           capture_output=True, text=True, check=True).stdout.split()
    files = sorted(f for f in files if f.endswith((".cpp", ".hpp")) and os.path.exists(os.path.join(root, f)))
    used = set()
    for f in files:
        text = open(os.path.join(root, f)).read()
        code, numbers = strip(text)
        names = allowed.get(f, {})
        spans = [c for c in constants(code) if c[0] in names]
        declared = {c[0] for c in spans}
        for name in names:
            if name not in declared:
                problems.append(f"{allow_path}:{names[name]}: {f} declares no constexpr {name} any more")
            else:
                used.add((f, name, False))
        for position, token in numbers:
            value = floating_value(token)
            if value is None or value in PLAIN:
                continue
            owner = next((c[0] for c in spans if c[1] <= position < c[2]), None)
            if owner is not None:
                used.add((f, owner))
                continue
            line = text.count("\n", 0, position) + 1
            problems.append(f"{f}:{line}: the literal {token} is not a named constant of {os.path.basename(allow_path)}"
                            " (a tuned number belongs in PlannerSettings, planner_settings.hpp)")
    for file, names in allowed.items():
        if file not in files:
            problems.append(f"{allow_path}:{min(names.values())}: {file} is not a source of planner/src")
            continue
        for name, number in names.items():
            if (file, name, False) in used and (file, name) not in used:
                problems.append(f"{allow_path}:{number}: {file}:{name} holds no literal other than 0, 1, 2 or 0.5;"
                                " drop it from the list")
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    here = os.path.dirname(os.path.abspath(__file__))
    sys.exit(main(sys.argv[1], sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "planner_literals_allowed.txt")))
