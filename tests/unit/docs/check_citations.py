#!/usr/bin/env python3
"""Fails on a comment or doc that cites something the project does not contain.

Usage: check_citations.py ROOT

Checked in every text file under ROOT (the build tree, .git and images skipped):
  - a cited file (`name.hpp`, `dir/name.cpp`, `docs/name.md`, ...) must exist in ROOT, or be
    generated from a file that does (cyberplanner/X.hpp from lcmtypes/X.lcm, X.cpp from X.cpp.in);
  - an equation cited as "eq. N", "eqs. N-M, P" must be defined in docs/algorithm.md, where each
    equation is marked "(eq. N)";
  - "X.md section N.M" (and "sections N and M") must name a numbered heading of docs/X.md;
  - X.md, "Heading" must name a heading of docs/X.md (its beginning).
Prints one line per broken citation, file:line first; exits 1 if there is any.
"""
import os
import re
import sys

SKIP_DIRS = {".git", "images", "__pycache__"}
TEXT_SUFFIXES = (".hpp", ".cpp", ".h", ".md", ".txt", ".cmake", ".sh", ".py", ".toml", ".lcm", ".java",
                 ".in", ".service", ".network", ".netdev", ".conf")
# Headers of the libraries the project builds on, cited where the project works around them.
LIBRARY_HEADERS = {"lcm-cpp-impl.hpp"}
FILE_CITATION = re.compile(r"(?<![\w./*$}-])((?:[\w.-]+/)*[\w-][\w.-]*\.(?:hpp|cpp|md))(?![\w])")
EQUATION_CITATION = re.compile(r"\beqs?\.\s*(\d+(?:\s*[-–]\s*\d+)?(?:\s*(?:,|and)\s*\d+(?:\s*[-–]\s*\d+)?)*)",
                               re.IGNORECASE)
EQUATION_LABEL = re.compile(r"\(eq\.\s*(\d+)\)")
SECTION_CITATION = re.compile(r"([\w-]+\.md)\s+(?:§|sections?\s+)(\d+(?:\.\d+)?(?:\s*(?:,|and)\s*\d+(?:\.\d+)?)*)")
PARAGRAPH_CITATION = re.compile(r"(?:§)(\d+(?:\.\d+)?)")
HEADING_CITATION = re.compile(r"([\w-]+\.md)[,:]?\s+\"([^\"]+)\"")
SELF = "tests/unit/docs/check_citations.py"  # its own help shows the forms it checks
FIXTURE = "tests/unit/docs/citation_fixture/"  # broken on purpose: the checker's own test
HEADING = re.compile(r"^#+\s+(.*?)\s*$")


def project_files(root):
    for directory, subdirs, files in os.walk(root):
        # Build trees (in-source or not) hold generated copies: skip any directory CMake built.
        subdirs[:] = [d for d in subdirs
                      if d not in SKIP_DIRS and not os.path.exists(os.path.join(directory, d, "CMakeCache.txt"))]
        for name in files:
            yield os.path.relpath(os.path.join(directory, name), root)


def exists(citation, paths, names):
    if citation in paths or citation in names:
        return True
    if "/.../" in citation:  # an elided middle: dir/.../name.hpp
        head, tail = citation.split("/.../", 1)
        return any(p.startswith(head + "/") and p.endswith("/" + tail) for p in paths)
    if "/" in citation:
        return any(p.endswith("/" + citation) for p in paths)
    return False


def generated(citation, paths, names):
    match = re.fullmatch(r"(?:.*/)?cyberplanner/(\w+)\.hpp", citation)
    if match:
        return "lcmtypes/" + match.group(1) + ".lcm" in paths
    return os.path.basename(citation) + ".in" in names


def numbers(text):
    out = []
    for part in re.split(r"\s*(?:,|and)\s*", text.strip()):
        bounds = re.split(r"\s*[-–]\s*", part)
        if len(bounds) == 2:
            out.extend(range(int(bounds[0]), int(bounds[1]) + 1))
        else:
            out.append(int(bounds[0]))
    return out


def headings(root, doc):
    path = os.path.join(root, "docs", doc)
    if not os.path.exists(path):
        return None
    with open(path, encoding="utf-8") as f:
        return [m.group(1) for line in f for m in [HEADING.match(line)] if m]


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    root = sys.argv[1]
    paths = set(project_files(root))
    names = {os.path.basename(p) for p in paths}
    algorithm = os.path.join(root, "docs", "algorithm.md")
    defined = set()
    if os.path.exists(algorithm):
        with open(algorithm, encoding="utf-8") as f:
            defined = {int(n) for n in EQUATION_LABEL.findall(f.read())}
    problems = []

    for rel in sorted(paths):
        if not rel.endswith(TEXT_SUFFIXES) or rel == SELF or rel.startswith(FIXTURE):
            continue
        try:
            with open(os.path.join(root, rel), encoding="utf-8") as f:
                lines = f.readlines()
        except UnicodeDecodeError:
            continue
        for number, line in enumerate(lines, 1):
            where = f"{rel}:{number}"
            if re.match(r"\s*#\s*include\s*<", line):
                continue  # system and library headers
            for citation in FILE_CITATION.findall(line):
                if citation.startswith(("_", ".")) or citation in LIBRARY_HEADERS:
                    continue
                if not exists(citation, paths, names) and not generated(citation, paths, names):
                    problems.append(f"{where}: cites {citation}, which the project does not contain")
            for group in EQUATION_CITATION.findall(line):
                for n in numbers(group):
                    if n not in defined:
                        problems.append(f"{where}: cites eq. {n}, which docs/algorithm.md does not define")
            for doc, group in SECTION_CITATION.findall(line):
                titles = headings(root, doc) or []
                for section in re.split(r"\s*(?:,|and)\s*", group.strip()):
                    if not any(re.match(re.escape(section) + r"\.?\s", t + " ") for t in titles):
                        problems.append(f"{where}: cites {doc} section {section}, which has no such heading")
            if "§" in line and "algorithm.md" in line:
                for section in PARAGRAPH_CITATION.findall(line):
                    titles = headings(root, "algorithm.md") or []
                    if not any(re.match(re.escape(section) + r"\.?\s", t + " ") for t in titles):
                        problems.append(f"{where}: cites algorithm.md §{section}, which has no such heading")
            for doc, title in HEADING_CITATION.findall(line):
                titles = headings(root, doc)
                if titles is not None and not any(t.startswith(title) for t in titles):
                    problems.append(f'{where}: cites {doc}, "{title}", which has no such heading')

    for problem in problems:
        print(problem)
    if problems:
        print(f"{len(problems)} citation(s) of things the project does not contain", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
