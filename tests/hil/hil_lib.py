"""Host-side readers for the HIL results: candump -L captures, LCM event logs, the plant
simulator's CSV (Python stdlib only). The wire formats are derived from their one definition each
rather than copied: the CAN ids and scales are read from the C++ codec's headers (can/include,
the source of truth for docs/can-protocol.md and tests/vectors/can_frames.txt), the LCM layouts
and fingerprints from lcmtypes/*.lcm, hashed the way lcm-gen hashes them. The decoding itself is
this file's own, so the checks do not reuse the C++ code under test; tests/hil/hil_lib_test.py
holds it to the shared CAN vectors and to the generated fingerprints."""

import csv
import os
import re
import bisect
import math
import struct

SOURCE_DIR = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

CANDUMP_LINE = re.compile(r"^\((\d+)\.(\d{6})\) (\S+) ([0-9A-F]{3}|[0-9A-F]{8})#(R|[0-9A-F]*)$")


def cpp_constants(*headers):
    """{kName: value} of every `inline constexpr TYPE kName = LITERAL;` in the headers (paths
    relative to the source tree); only plain integer and floating literals."""
    found = {}
    for header in headers:
        with open(os.path.join(SOURCE_DIR, header)) as f:
            text = f.read()
        for name, literal in re.findall(r"inline constexpr [\w:]+ (k\w+) = ([0-9][0-9a-fA-FxX.eE+-]*)u?;", text):
            found[name] = int(literal, 0) if re.fullmatch(r"0[xX][0-9a-fA-F]+|\d+", literal) else float(literal)
    return found


CAN = cpp_constants("can/include/cyber/can/frc_id.hpp", "can/include/cyber/can/setpoint_codec.hpp")
HEARTBEAT_ID = CAN["kHeartbeatId"]
# FRC CAN id: device type << 24 | manufacturer << 16 | (api class << 4 | api index) << 6 | device.
TEAM_PREFIX = (CAN["kDeviceTypeMiscellaneous"] << 24) | (CAN["kManufacturerTeamUse"] << 16)
POSITION_COUNTS = CAN["kPositionCountsPerUnit"]
VELOCITY_COUNTS = CAN["kVelocityCountsPerUnit"]
VOLTAGE_COUNTS = CAN["kVoltageCountsPerVolt"]


def team_frame_id(api_class, api_index, device):
    return TEAM_PREFIX | (((api_class << 4) | api_index) << 6) | device


def setpoint_id(device):
    return team_frame_id(CAN["kSetpointApiClass"], CAN["kSetpointApiIndex"], device)


def status_id(device):
    return team_frame_id(CAN["kStatusApiClass"], CAN["kStatusApiIndex"], device)


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
    position = signed(d[0] | d[1] << 8 | d[2] << 16, 24) / POSITION_COUNTS
    velocity = signed(d[3] | d[4] << 8, 16) / VELOCITY_COUNTS
    volts = signed(d[5] | d[6] << 8, 16) / VOLTAGE_COUNTS
    return position, velocity, volts, d[7]


def encode_setpoint(position, velocity, volts, sequence):
    """The 8 payload bytes, rounding halves away from zero (docs/can-protocol.md)."""
    def count(value, scale, bits):
        c = int(abs(value) * scale + 0.5) * (1 if value >= 0 else -1)
        assert -(1 << (bits - 1)) <= c < (1 << (bits - 1)), (value, bits)
        return c & ((1 << bits) - 1)
    p = count(position, POSITION_COUNTS, 24)
    v, u = count(velocity, VELOCITY_COUNTS, 16), count(volts, VOLTAGE_COUNTS, 16)
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


LCM_PRIMITIVES = {"int8_t": "b", "int16_t": "h", "int32_t": "i", "int64_t": "q", "float": "f", "double": "d",
                  "boolean": "b", "byte": "B", "string": None}


def lcm_members(type_name):
    """[(name, type, [dimension sizes])] of lcmtypes/TYPE_NAME.lcm, constants left out."""
    with open(os.path.join(SOURCE_DIR, "lcmtypes", type_name + ".lcm")) as f:
        text = re.sub(r"//[^\n]*", "", f.read())
    members = []
    for decl in text[text.index("{") + 1:text.rindex("}")].split(";"):
        decl = decl.strip()
        if not decl or decl.startswith("const "):
            continue
        m = re.fullmatch(r"(\w+)\s+(\w+)((?:\s*\[\s*\w+\s*\])*)", decl)
        if not m or m.group(1) not in LCM_PRIMITIVES:
            raise ValueError(f"lcmtypes/{type_name}.lcm: cannot read '{decl}'")
        members.append((m.group(2), m.group(1), re.findall(r"\[\s*(\w+)\s*\]", m.group(3))))
    return members


def lcm_fingerprint(members):
    """The 8-byte fingerprint lcm-gen gives a struct of primitive members: a hash of each member's
    name, type and dimensions (a dimension is constant, 0, or sized by a member, 1), rotated left
    by one bit as the generated _computeHash does for a struct with no nested types."""
    mask = (1 << 64) - 1

    def update(v, c):
        c = c - 256 if c > 127 else c  # lcm-gen adds a (signed) char
        v = (((v << 8) ^ (v >> 55)) + c) & mask
        return v - (1 << 64) if v >> 63 else v

    def update_text(v, text):
        v = update(v, len(text))
        for c in text.encode():
            v = update(v, c)
        return v

    v = 0x12345678
    for name, type_name, dims in members:
        v = update_text(update_text(v, name), type_name)
        v = update(v, len(dims))
        for size in dims:
            v = update_text(update(v, 0 if size.isdigit() else 1), size)
    v &= mask
    return ((v << 1) & mask) | (v >> 63)


class LcmType:
    """One message type of lcmtypes/: decode() checks the fingerprint, then reads the members in
    order (big-endian) into a dict."""

    def __init__(self, type_name):
        self.name, self.members = type_name, lcm_members(type_name)
        self.fingerprint = lcm_fingerprint(self.members)

    def decode(self, data):
        try:
            return self._decode(data)
        except struct.error as e:
            raise ValueError(f"{self.name}: truncated message ({len(data)} bytes): {e}") from None

    def _decode(self, data):
        (fingerprint,) = struct.unpack_from(">Q", data, 0)
        if fingerprint != self.fingerprint:
            raise ValueError(f"{self.name}: fingerprint {fingerprint:#018x}, expected {self.fingerprint:#018x}")
        at, out = 8, {}
        for name, type_name, dims in self.members:
            count = 1
            for size in dims:
                count *= int(size) if size.isdigit() else out[size]
            values = []
            for _ in range(count):
                if type_name == "string":
                    (n,) = struct.unpack_from(">i", data, at)
                    values.append(data[at + 4:at + 4 + n - 1].decode())
                    at += 4 + n
                else:
                    (value,) = struct.unpack_from(">" + LCM_PRIMITIVES[type_name], data, at)
                    values.append(bool(value) if type_name == "boolean" else value)
                    at += struct.calcsize(">" + LCM_PRIMITIVES[type_name])
            # A [num_joints][num_samples] member comes back as num_joints rows (each of
            # num_samples, maybe none), as lcm-gen's nested vectors.
            sizes = [int(size) if size.isdigit() else out[size] for size in dims]
            for k in range(len(sizes) - 1, 0, -1):
                n, rows = sizes[k], math.prod(sizes[:k])
                values = [values[i * n:(i + 1) * n] for i in range(rows)]
            out[name] = values if dims else values[0]
        if at != len(data):
            raise ValueError(f"{self.name}: {len(data) - at} bytes after the last member")
        return out


ARM_STATE = LcmType("arm_state_t")
ARM_PLAN_STATUS = LcmType("arm_plan_status_t")
ARM_TRAJECTORY = LcmType("arm_trajectory_t")
ARM_DAEMON_STATUS = LcmType("arm_daemon_status_t")


def decode_arm_state(data):
    return ARM_STATE.decode(data)


def decode_plan_status(data):
    return ARM_PLAN_STATUS.decode(data)


def decode_trajectory(data):
    return ARM_TRAJECTORY.decode(data)


def decode_daemon_status(data):
    return ARM_DAEMON_STATUS.decode(data)


# --- plant simulator ---------------------------------------------------------------------------

def plant_columns(config):
    """The column names cyber-plant-sim --log gives each joint of a loaded config, in [[joints]]
    order (NAME_UNIT, UNIT m for a prismatic joint, rad for a revolute one) as a list of dicts: q
    (position), v (velocity), cmd_q, cmd_v, ff_volts, volts. The reference robot's are
    elevator_m, elevator_mps, ... and arm_rad, arm_radps, ...."""
    out = []
    for joint in config["joints"]:
        name, unit = joint["name"], "m" if joint["type"] == "prismatic" else "rad"
        out.append(dict(q=f"{name}_{unit}", v=f"{name}_{unit}ps", cmd_q=f"{name}_cmd_{unit}",
                        cmd_v=f"{name}_cmd_{unit}ps", ff_volts=f"{name}_ff_volts", volts=f"{name}_volts"))
    return out


def read_plant_csv(path):
    """Rows of cyber-plant-sim --log as dicts of floats (None for empty fields)."""
    rows = []
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            rows.append({k: (float(v) if v != "" else None) for k, v in row.items()})
    return rows


def final_from_goal_output(path, request_id, status_codes):
    """The final status cyber-goal printed for request_id ("request N cancelled: reason") as
    {request_id, status (its code in status_codes), reason}, or None without such a line."""
    if not os.path.exists(path):
        return None
    finals = "|".join(name for name, code in status_codes.items() if code >= status_codes["done"])
    found = None
    with open(path) as f:
        for line in f:
            m = re.match(rf"request {request_id} ({finals})(?:: (.*))?$", line.rstrip("\n"))
            if m:
                found = {"request_id": request_id, "status": status_codes[m.group(1)], "reason": m.group(2) or ""}
    return found


def published_around(rows, t_stop, t_resume):
    """The last ARM_STATE the simulator published at or before t_stop and the first at or after
    t_resume (wall s; 1 ms of slack for the fault's own log line), from its --log rows: a published
    row carries the message's utime. A recorder can miss messages; these rows cannot."""
    published = [r["utime"] * 1e-6 for r in rows if r["state_published"] == 1]
    return (max(t for t in published if t <= t_stop + 0.001), min(t for t in published if t >= t_resume - 0.001))


def plant_summary(path):
    """The counters of cyber-plant-sim's closing 'stopped:' line on stderr, for any number of
    joints (the line names them as the config does; here they go by index): joint0, joint1, ...
    (final positions), setpoints_joint0, ..., the counters after them, and joints (how many)."""
    text = open(path).read()
    m = re.search(r"stopped: ([^ ;,]+ \S+ (?:m|rad)(?:, [^ ;,]+ \S+ (?:m|rad))*); setpoints ([^ ;,]+ \d+(?: [^ ;,]+ \d+)*), "
                  r"sequence gaps (\d+), malformed (\d+), other (\d+), bus errors (\d+), read failures (\d+); "
                  r"sent heartbeats (\d+), disables (\d+), write failures (\d+); "
                  r"ARM_STATE published (\d+), failed (\d+); motions (\d+); frozen (\d+) times, (\S+) s", text)
    if not m:
        raise ValueError(f"{path}: no 'stopped:' summary line")
    positions = [float(part.split()[1]) for part in m.group(1).split(", ")]
    counts = [float(v) for v in m.group(2).split()[1::2]]
    if len(counts) != len(positions):
        raise ValueError(f"{path}: {len(positions)} positions but {len(counts)} setpoint counts")
    summary = {"joints": float(len(positions))}
    summary.update({f"joint{j}": q for j, q in enumerate(positions)})
    summary.update({f"setpoints_joint{j}": n for j, n in enumerate(counts)})
    keys = ("sequence_gaps", "malformed", "other", "bus_errors", "read_failures", "heartbeats", "disables",
            "write_failures", "states_published", "publish_failures", "motions", "freezes", "frozen_s")
    summary.update({k: float(v) for k, v in zip(keys, m.groups()[2:])})
    return summary


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


def longest_gap(times, t0, t1, default=float("nan")):
    """The longest interval between consecutive times that overlaps [t0, t1] (sorted times), or
    `default` when fewer than two times are near."""
    i = max(bisect.bisect_left(times, t0) - 1, 0)
    j = min(bisect.bisect_right(times, t1) + 1, len(times))
    near = times[i:j]
    return max((b - a for a, b in zip(near, near[1:]) if b >= t0 and a <= t1), default=default)
