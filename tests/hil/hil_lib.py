"""Host-side readers for the HIL results: candump -L captures, LCM event logs, the plant
simulator's CSV. An independent reading of docs/can-protocol.md and docs/lcm.md (Python stdlib
only), so the checks do not reuse the C++ code under test."""

import csv
import os
import re
import bisect
import struct

CANDUMP_LINE = re.compile(r"^\((\d+)\.(\d{6})\) (\S+) ([0-9A-F]{3}|[0-9A-F]{8})#(R|[0-9A-F]*)$")

HEARTBEAT_ID = 0x01011840
TEAM_PREFIX = (10 << 24) | (8 << 16)  # device type Miscellaneous, manufacturer Team Use


def setpoint_id(device):
    return TEAM_PREFIX | (((1 << 4) | 0) << 6) | device


def status_id(device):
    return TEAM_PREFIX | (((2 << 4) | 0) << 6) | device


class Frame:
    __slots__ = ("t", "iface", "id", "extended", "remote", "data")

    def __init__(self, t, iface, can_id, extended, remote, data):
        self.t, self.iface, self.id, self.extended, self.remote, self.data = t, iface, can_id, extended, remote, data


def read_candump(path):
    """Frames of a candump -L log; raises on a line that is not a record."""
    frames = []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            line = line.rstrip("\n")
            m = CANDUMP_LINE.match(line)
            if not m:
                raise ValueError(f"{path}:{number}: not a candump -L record: {line!r}")
            t = int(m.group(1)) + int(m.group(2)) * 1e-6
            ident, payload = m.group(4), m.group(5)
            remote = payload == "R"
            data = b"" if remote else bytes.fromhex(payload)
            frames.append(Frame(t, m.group(3), int(ident, 16), len(ident) == 8, remote, data))
    return frames


def signed(value, bits):
    return value - (1 << bits) if value & (1 << (bits - 1)) else value


def decode_setpoint(frame):
    """(position, velocity, volts, sequence) of an 8-byte setpoint payload."""
    d = frame.data
    position = signed(d[0] | d[1] << 8 | d[2] << 16, 24) * 1e-5
    velocity = signed(d[3] | d[4] << 8, 16) * 1e-3
    volts = signed(d[5] | d[6] << 8, 16) * 1e-3
    return position, velocity, volts, d[7]


def encode_setpoint(position, velocity, volts, sequence):
    """The 8 payload bytes, rounding halves away from zero (docs/can-protocol.md)."""
    def count(value, scale, bits):
        c = int(abs(value) * scale + 0.5) * (1 if value >= 0 else -1)
        assert -(1 << (bits - 1)) <= c < (1 << (bits - 1)), (value, bits)
        return c & ((1 << bits) - 1)
    p, v, u = count(position, 1e5, 24), count(velocity, 1e3, 16), count(volts, 1e3, 16)
    return bytes([p & 0xFF, p >> 8 & 0xFF, p >> 16, v & 0xFF, v >> 8, u & 0xFF, u >> 8, sequence & 0xFF])


def candump_line(t, iface, can_id, data, extended=True):
    ident = f"{can_id:08X}" if extended else f"{can_id:03X}"
    return f"({int(t)}.{round((t - int(t)) * 1e6):06d}) {iface} {ident}#{data.hex().upper()}"


# --- LCM ---------------------------------------------------------------------------------------

LCM_SYNC = 0xEDA1DA01


def read_lcm_log(path):
    """(timestamp_us, channel, payload) of every event in an LCM log file."""
    events = []
    with open(path, "rb") as f:
        blob = f.read()
    at = 0
    while at + 28 <= len(blob):
        sync, _number, utime, channel_len, data_len = struct.unpack_from(">IqqII", blob, at)
        if sync != LCM_SYNC:
            raise ValueError(f"{path}: bad sync word at byte {at}")
        at += 28
        if at + channel_len + data_len > len(blob):
            break  # the logger was stopped mid-write
        channel = blob[at:at + channel_len].decode()
        at += channel_len
        events.append((utime, channel, blob[at:at + data_len]))
        at += data_len
    return events


class Reader:
    """Big-endian LCM field reader; skips the 8-byte fingerprint."""

    def __init__(self, data):
        self.data, self.at = data, 8

    def take(self, fmt):
        value = struct.unpack_from(">" + fmt, self.data, self.at)
        self.at += struct.calcsize(">" + fmt)
        return value if len(value) > 1 else value[0]

    def string(self):
        n = self.take("i")
        text = self.data[self.at:self.at + n - 1].decode()
        self.at += n
        return text


def decode_arm_state(data):
    r = Reader(data)
    utime, e, ev, a, av, coral, algae = r.take("qddddbb")
    return dict(utime=utime, elevator_m=e, elevator_mps=ev, arm_rad=a, arm_radps=av,
                held_coral=bool(coral), held_algae=bool(algae))


def decode_plan_status(data):
    r = Reader(data)
    utime, request_id, status = r.take("qqb")
    reason = r.string()
    grid, search, smooth, topp, total, duration = r.take("dddddd")
    return dict(utime=utime, request_id=request_id, status=status, reason=reason, grid_ms=grid,
                search_ms=search, smooth_ms=smooth, topp_ms=topp, total_ms=total, duration_s=duration)


def decode_trajectory(data):
    r = Reader(data)
    utime, request_id, start_utime, duration, dt, n = r.take("qqqddi")
    columns = {}
    for name in ("t_s", "elevator_m", "arm_rad", "elevator_mps", "arm_radps", "elevator_volts", "arm_volts"):
        columns[name] = list(r.take(f"{n}d")) if n > 1 else ([r.take("d")] if n == 1 else [])
    return dict(utime=utime, request_id=request_id, start_utime=start_utime, duration_s=duration,
                dt_s=dt, num_samples=n, **columns)


DAEMON_STATUS_FIELDS = (
    ("utime", "q"), ("mode", "b"), ("robot_enabled", "b"), ("motion_allowed", "b"),
    ("active_request_id", "q"), ("state_age_ms", "d"), ("heartbeat_age_ms", "d"),
    ("goals_received", "q"), ("plans_succeeded", "q"), ("plans_failed", "q"), ("frames_sent", "q"),
    ("can_errors", "q"), ("decode_errors", "q"), ("stream_overruns", "q"), ("publish_failures", "q"),
    ("plan_time_p50_ms", "d"), ("plan_time_p99_ms", "d"), ("plan_time_max_ms", "d"),
    ("stream_jitter_p50_us", "d"), ("stream_jitter_p99_us", "d"), ("stream_jitter_max_us", "d"),
    ("realtime_priority", "i"))


def decode_daemon_status(data):
    r = Reader(data)
    return {name: r.take(fmt) for name, fmt in DAEMON_STATUS_FIELDS}


# --- plant simulator ---------------------------------------------------------------------------

def read_plant_csv(path):
    """Rows of cyber-plant-sim --log as dicts of floats (None for empty fields)."""
    rows = []
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            rows.append({k: (float(v) if v != "" else None) for k, v in row.items()})
    return rows


def plant_summary(path):
    """The counters of cyber-plant-sim's closing 'stopped:' line on stderr."""
    text = open(path).read()
    m = re.search(r"stopped: elevator (\S+) m, arm (\S+) rad; setpoints elevator (\d+) arm (\d+), "
                  r"sequence gaps (\d+), malformed (\d+), other (\d+), bus errors (\d+), read failures (\d+); "
                  r"sent heartbeats (\d+), disables (\d+), write failures (\d+); "
                  r"ARM_STATE published (\d+), failed (\d+); motions (\d+); frozen (\d+) times, (\S+) s", text)
    if not m:
        raise ValueError(f"{path}: no 'stopped:' summary line")
    keys = ("elevator_m", "arm_rad", "setpoints_elevator", "setpoints_arm", "sequence_gaps", "malformed",
            "other", "bus_errors", "read_failures", "heartbeats", "disables", "write_failures",
            "states_published", "publish_failures", "motions", "freezes", "frozen_s")
    return {k: float(v) for k, v in zip(keys, m.groups())}


def percentile(values, p):
    s = sorted(values)
    if not s:
        return float("nan")
    k = (len(s) - 1) * p / 100.0
    lo = int(k)
    hi = min(lo + 1, len(s) - 1)
    return s[lo] + (s[hi] - s[lo]) * (k - lo)


class Checks:
    """Collects pass/fail lines; exit status 1 if any failed."""

    def __init__(self, name):
        self.name, self.failed = name, 0

    def check(self, ok, what):
        print(f"{self.name}: {'ok  ' if ok else 'FAIL'} {what}")
        if not ok:
            self.failed += 1
        return ok

    def note(self, what):
        print(f"{self.name}: note {what}")

    def status(self):
        print(f"{self.name}: {'all checks passed' if not self.failed else f'{self.failed} check(s) failed'}")
        return 1 if self.failed else 0


def plant_events(path):
    """(wall time s, text) of each line cyber-plant-sim logged on stderr."""
    events = []
    for line in open(path):
        m = re.match(r"cyber-plant-sim: t=\S+ \[(\d+)\.(\d{6})\] (.*)$", line.rstrip("\n"))
        if m:
            events.append((int(m.group(1)) + int(m.group(2)) * 1e-6, m.group(3)))
    return events


def read_scenario(path):
    """KEY=VALUE lines the guest script noted, as {key: [values]}."""
    notes = {}
    if os.path.exists(path):
        for line in open(path):
            key, _, value = line.strip().partition("=")
            notes.setdefault(key, []).append(value)
    return notes


def longest_gap(times, t0, t1):
    """The longest interval between consecutive times that overlaps [t0, t1] (sorted times)."""
    i = max(bisect.bisect_left(times, t0) - 1, 0)
    j = min(bisect.bisect_right(times, t1) + 1, len(times))
    near = times[i:j]
    return max((b - a for a, b in zip(near, near[1:]) if b >= t0 and a <= t1), default=float("nan"))
