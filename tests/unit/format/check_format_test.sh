#!/bin/bash
# usage: check_format_test.sh CLANG_FORMAT SOURCE_DIR
# Every C++ source of the project is as .clang-format lays it out; and the check itself fails on
# a file that is not (so this test can fail).
set -euo pipefail
clang_format=$1 src=$2
cd "$src"
if [ -d .git ] || git rev-parse --git-dir >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h')
else
  mapfile -t files < <(find . -path ./build -prune -o \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' \) -print)
fi
[ "${#files[@]}" -gt 100 ] || { echo "FAIL: only ${#files[@]} C++ files found in $src"; exit 1; }

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp .clang-format "$tmp/"
printf 'int  f( int x ){return x;}\n' >"$tmp/badly_laid_out.cpp"
if "$clang_format" --dry-run --Werror "$tmp/badly_laid_out.cpp" 2>/dev/null; then
  echo "FAIL: clang-format accepted a badly laid out file"
  exit 1
fi

if ! "$clang_format" --dry-run --Werror "${files[@]}" 2>"$tmp/report"; then
  grep -E '^[^ ].*: (error|warning):' "$tmp/report" | cut -d: -f1 | sort -u | sed 's/^/not laid out as .clang-format says: /'
  echo "FAIL: run: clang-format-14 -i \$(git ls-files '*.cpp' '*.hpp' '*.h')"
  exit 1
fi
echo "${#files[@]} C++ files follow .clang-format"
