#!/usr/bin/env bash
# daemon.core_is_pure: daemon/core (docs/design.md, "Components") includes no thread, clock,
# atomic, socket or system header and nothing of daemon/io or the CAN socket; then the check
# itself, on a copy of daemon/core with one such include added, must fail.
set -euo pipefail
core=$1/daemon/core
forbidden='^#include[[:space:]]*(<(thread|atomic|mutex|condition_variable|chrono|ctime|time\.h|unistd\.h|fcntl\.h|pthread\.h|sys/[^>]*|linux/[^>]*|net/[^>]*)>|"cyber/daemon/io/[^"]*"|"cyber/can/can_socket\.hpp")'

check() {
  if grep -rnE "$forbidden" "$1"; then
    echo "daemon/core must stay free of threads, clocks and I/O (move the code above to daemon/io)" >&2
    return 1
  fi
}

check "$core"

copy=$(mktemp -d)
trap 'rm -rf "$copy"' EXIT
cp -r "$core/." "$copy"
echo '#include <thread>' >> "$copy/src/streamer.cpp"
if check "$copy" > /dev/null 2>&1; then
  echo "the check missed an include of <thread>" >&2
  exit 1
fi
