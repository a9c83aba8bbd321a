#!/usr/bin/env bash
# docs.citations: every file, equation and section a comment or doc cites exists in the project;
# and the checker reports each kind of broken citation in citation_fixture/ (a tree whose
# citations all exist, then the same tree with the fixture's broken header added).
set -euo pipefail
here=$(dirname "$0")
checker=$here/check_citations.py
src=$1

python3 "$checker" "$src"

tree=$(mktemp -d)
trap 'rm -rf "$tree"' EXIT
cp -r "$here/citation_fixture/tree/." "$tree"
if ! python3 "$checker" "$tree" > "$tree/out"; then
  cat "$tree/out"
  echo "citations that exist were reported" >&2
  exit 1
fi
cp "$here"/citation_fixture/broken.* "$tree/lib/"
if python3 "$checker" "$tree" > "$tree/out"; then
  echo "the checker passed a tree with broken citations" >&2
  exit 1
fi
# One report per broken citation, each naming its line: citation_fixture/expected.txt.
diff -u "$here/citation_fixture/expected.txt" "$tree/out" || { echo "the checker's reports differ" >&2; exit 1; }
echo "citations: all present; the checker reports each kind of broken one"
