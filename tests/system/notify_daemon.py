#!/usr/bin/env python3
"""system.notify_daemon: cyber-plannerd under a fake service manager.

Plays systemd's part for a Type=notify service with WatchdogSec: binds a datagram socket, starts
the daemon with NOTIFY_SOCKET, WATCHDOG_USEC and WATCHDOG_PID (its own pid, as systemd sets it),
and checks what arrives: READY=1, WATCHDOG=1 at least every WATCHDOG_USEC/2, a one-line STATUS=,
every datagram from the daemon's own pid (what NotifyAccess=main accepts), then on SIGTERM
STOPPING=1 and exit status 0.

usage: notify_daemon.py DAEMON CONFIG
"""

import os
import signal
import socket
import struct
import sys
import tempfile
import time

WATCHDOG_USEC = 1_000_000
READY_TIMEOUT_S = 60.0
WATCH_S = 3.0
STOP_TIMEOUT_S = 15.0


def fail(message):
    print(f"FAIL: {message}", file=sys.stderr)
    sys.exit(1)


class FakeManager:
    def __init__(self, path):
        self.sock = socket.socket(socket.AF_UNIX, socket.SOCK_DGRAM)
        self.sock.bind(path)
        self.sock.setsockopt(socket.SOL_SOCKET, socket.SO_PASSCRED, 1)
        self.log = []  # (time, pid, fields)

    def receive(self, timeout_s):
        """One datagram as (pid, {key: value}), or None after timeout_s."""
        self.sock.settimeout(max(timeout_s, 0.001))
        try:
            data, ancillary, _, _ = self.sock.recvmsg(4096, socket.CMSG_SPACE(12))
        except socket.timeout:
            return None
        pid = None
        for level, kind, payload in ancillary:
            if level == socket.SOL_SOCKET and kind == socket.SCM_CREDENTIALS:
                pid, _, _ = struct.unpack("iII", payload[:12])
        fields = {}
        for line in data.decode("utf-8", "replace").split("\n"):
            if "=" not in line:
                fail(f"datagram line without '=': {line!r} in {data!r}")
            key, value = line.split("=", 1)
            fields[key] = value
        self.log.append((time.monotonic(), pid, fields))
        return pid, fields


def start_daemon(daemon, config, notify_socket):
    child = os.fork()
    if child == 0:
        env = dict(os.environ)
        env["NOTIFY_SOCKET"] = notify_socket
        env["WATCHDOG_USEC"] = str(WATCHDOG_USEC)
        env["WATCHDOG_PID"] = str(os.getpid())
        try:
            os.execve(daemon, [daemon, "--config", config, "--can", "none", "--lcm-url", "memq://"], env)
        finally:
            os._exit(127)
    return child


_exit_status = {}


def exited(pid):
    """Exit status if the process has ended (reaped once, remembered), else None."""
    if pid not in _exit_status:
        done, status = os.waitpid(pid, os.WNOHANG)
        if not done:
            return None
        _exit_status[pid] = os.waitstatus_to_exitcode(status)
    return _exit_status[pid]


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    daemon, config = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory(prefix="cyber-notify-") as tmp:
        path = os.path.join(tmp, "notify")
        manager = FakeManager(path)
        pid = start_daemon(daemon, config, path)
        try:
            return run_checks(manager, pid)
        finally:
            if exited(pid) is None:
                os.kill(pid, signal.SIGKILL)
                os.waitpid(pid, 0)


def run_checks(manager, pid):
    # 1. READY=1 once start-up is done.
    deadline = time.monotonic() + READY_TIMEOUT_S
    ready_at = None
    while ready_at is None:
        if time.monotonic() > deadline:
            fail(f"no READY=1 within {READY_TIMEOUT_S} s")
        status = exited(pid)
        if status is not None:
            fail(f"cyber-plannerd exited with status {status} before READY=1")
        got = manager.receive(0.5)
        if got and got[1].get("READY") == "1":
            ready_at = time.monotonic()
    print("READY=1 after start-up")

    # 2. Watchdog pings and status while it runs.
    while time.monotonic() < ready_at + WATCH_S:
        manager.receive(ready_at + WATCH_S - time.monotonic())
    if exited(pid) is not None:
        fail("cyber-plannerd exited while running")
    pings = [t for t, _, fields in manager.log if fields.get("WATCHDOG") == "1" and t >= ready_at]
    if len(pings) < 4:
        fail(f"{len(pings)} WATCHDOG=1 in the {WATCH_S} s after READY=1 (WATCHDOG_USEC={WATCHDOG_USEC})")
    gaps = [b - a for a, b in zip([ready_at] + pings, pings)]
    if max(gaps) > WATCHDOG_USEC / 1e6:
        fail(f"WATCHDOG=1 gap of {max(gaps):.3f} s exceeds WATCHDOG_USEC ({WATCHDOG_USEC / 1e6} s)")
    statuses = [fields["STATUS"] for _, _, fields in manager.log if "STATUS" in fields]
    if not statuses or not statuses[-1].strip():
        fail(f"no non-empty STATUS= (got {statuses})")
    print(f"{len(pings)} WATCHDOG=1 in {WATCH_S} s (largest gap {max(gaps):.3f} s); last STATUS={statuses[-1]}")

    # 3. SIGTERM: STOPPING=1 and a clean exit.
    os.kill(pid, signal.SIGTERM)
    deadline = time.monotonic() + STOP_TIMEOUT_S
    status = None
    while status is None and time.monotonic() < deadline:
        manager.receive(0.1)
        status = exited(pid)
    while manager.receive(0.05):
        pass
    if status is None:
        fail(f"cyber-plannerd still running {STOP_TIMEOUT_S} s after SIGTERM")
    if status != 0:
        fail(f"cyber-plannerd exited with status {status} after SIGTERM")
    if not any(fields.get("STOPPING") == "1" for _, _, fields in manager.log):
        fail("no STOPPING=1 after SIGTERM")

    # systemd (NotifyAccess=main) accepts only datagrams from the main pid.
    foreign = {sender for _, sender, _ in manager.log if sender != pid}
    if foreign:
        fail(f"datagrams from pids {sorted(foreign)}, not the daemon's pid {pid}")
    print(f"STOPPING=1 and exit status 0; all {len(manager.log)} datagrams from pid {pid}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
