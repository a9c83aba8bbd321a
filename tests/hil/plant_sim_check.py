#!/usr/bin/env python3
"""Host side of hil.plant_sim: makes the setpoint stream the guest replays with canplayer, and
checks what cyber-plant-sim did with it (docs/testing.md, "Plant simulator").

  plant_sim_check.py setpoints FILE   write the candump -L log canplayer replays
  plant_sim_check.py check OUT_DIR    check the results the guest wrote (exit 1 on a failure)
"""

import math
import os
import statistics
import sys
import tomllib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hil_lib as hil  # noqa: E402

SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PERIOD_S = 0.005
HOLD_BEFORE_S, MOVE_S, HOLD_AFTER_S = 0.3, 1.0, 0.5
ELEVATOR_FROM, ELEVATOR_TO, ARM_AT = 0.5, 1.0, 1.57
# The faults of the guest script, relative to the first moving setpoint (tests/hil/plant_sim.sh).
HEARTBEAT_GAP = (0.4, 0.6)
HEARTBEAT_DISABLED = (0.8, 0.9)
SILENT = (1.0, 1.2)
DISABLE_AT = 1.3
# Data frames the guest sends with our setpoint ids but a wrong length (its remote request is
# dropped by the receive filter, which passes data frames only).
MALFORMED_SENT = 2


def load_config():
    with open(os.path.join(SOURCE, "config", "reefscape-2025.toml"), "rb") as f:
        return tomllib.load(f)


# plant.csv's columns of joint 0 (the elevator) and joint 1 (the arm), named by the config.
ELEVATOR, ARM = hil.plant_columns(load_config())


def drive(name):
    with open(os.path.join(SOURCE, "config", "reefscape-2025.toml"), "rb") as f:
        return tomllib.load(f)["drives"][name]


def volts(d, q, v, a, cosine):
    sign = (v > 0) - (v < 0)
    return d["kS_volts"] * sign + d["kG_volts"] * (math.cos(q) if cosine else 1.0) + d["kV"] * v + d["kA"] * a


def elevator_plan(t):
    """Rest-to-rest quintic from ELEVATOR_FROM to ELEVATOR_TO starting at HOLD_BEFORE_S."""
    s = min(max((t - HOLD_BEFORE_S) / MOVE_S, 0.0), 1.0)
    d = ELEVATOR_TO - ELEVATOR_FROM
    q = ELEVATOR_FROM + d * s ** 3 * (10 - 15 * s + 6 * s * s)
    v = d * 30 * s * s * (1 - s) ** 2 / MOVE_S
    a = d * 60 * s * (1 - s) * (1 - 2 * s) / MOVE_S ** 2
    return q, v, a


def write_setpoints(path):
    elevator, arm = drive("elevator"), drive("arm")
    lines = []
    n = int(round((HOLD_BEFORE_S + MOVE_S + HOLD_AFTER_S) / PERIOD_S)) + 1
    for k in range(n):
        t = k * PERIOD_S
        q, v, a = elevator_plan(t)
        stamp = 1000.0 + t
        lines.append(hil.candump_line(stamp, "can0", hil.setpoint_id(1),
                                      hil.encode_setpoint(q, v, volts(elevator, q, v, a, False), k)))
        lines.append(hil.candump_line(stamp + 50e-6, "can0", hil.setpoint_id(2),
                                      hil.encode_setpoint(ARM_AT, 0.0, volts(arm, ARM_AT, 0, 0, True), k)))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def stall_near(reference, t):
    """The longest gap in the reference times (the simulator's CSV rows, every 10 ms whatever it
    publishes) within 0.3 s of t: how long the emulated guest stood still around then."""
    return hil.longest_gap(reference, t - 0.3, t + 0.3, default=0.0)


def silent_window(c, what, times, window, reference):
    """True when nothing was seen inside the window (5 ms inside its edges) and something was seen
    close to both edges: within 50 ms plus however long the guest stood still there. The longest
    gap outside the window is reported: the emulated guest sometimes stalls."""
    start, end = window
    inside = [t for t in times if start + 0.005 < t < end - 0.005]
    before = [t for t in times if start - 0.05 - stall_near(reference, start) <= t <= start + 0.005]
    after = [t for t in times if end - 0.005 <= t <= end + 0.05 + stall_near(reference, end)]
    gaps = sorted(((b - a, a) for a, b in zip(times, times[1:]) if not (a <= start + 0.005 and b >= end - 0.005)),
                  reverse=True)
    if gaps:
        c.note(f"{what}: longest gap outside the window {gaps[0][0] * 1e3:.1f} ms at motion{gaps[0][1]:+.3f} s")
    return not inside and before and after


def regular_before(frames, i, window_s):
    """True when the frames before frames[i] came at 5 +- 2 ms periods for at least window_s."""
    j = i
    while j > 0:
        if abs(frames[j].t - frames[j - 1].t - PERIOD_S) > 0.002:
            return False
        if frames[i].t - frames[j - 1].t > window_s:
            return True
        j -= 1
    return False


def interpolate(rows, key, utime):
    """Linear interpolation of a CSV column at a wall-clock time (us)."""
    lo, hi = 0, len(rows) - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if rows[mid]["utime"] <= utime:
            lo = mid
        else:
            hi = mid
    a, b = rows[lo], rows[hi]
    if b["utime"] == a["utime"]:
        return a[key]
    w = min(max((utime - a["utime"]) / (b["utime"] - a["utime"]), 0.0), 1.0)
    return a[key] + w * (b[key] - a[key])


def check(out):
    c = hil.Checks("plant_sim")
    frames = hil.read_candump(os.path.join(out, "bus.log"))
    rows = hil.read_plant_csv(os.path.join(out, "plant.csv"))
    summary = hil.plant_summary(os.path.join(out, "plant_sim.err"))
    states = [hil.decode_arm_state(d) for _, ch, d in hil.read_lcm_log(os.path.join(out, "lcm.log")) if ch == "ARM_STATE"]

    elevator_sp = [f for f in frames if f.extended and f.id == hil.setpoint_id(1) and len(f.data) == 8]
    arm_sp = [f for f in frames if f.extended and f.id == hil.setpoint_id(2) and len(f.data) == 8]
    moving = [f for f in elevator_sp if abs(hil.decode_setpoint(f)[1]) >= 0.001]
    if not c.check(moving, f"replayed setpoints captured ({len(elevator_sp)} elevator, {len(arm_sp)} arm)"):
        return c.status()
    # Times relative to the motion start as the simulator saw it (its log has the wall clock):
    # each fault must come at its scheduled offset from there, and the checks below look at the
    # windows between the faults as actually applied.
    events = hil.plant_events(os.path.join(out, "plant_sim.err"))
    seen = [t for t, text in events if text.startswith("motion 1 started")]
    if not c.check(seen, "the simulator logged the start of motion 1"):
        return c.status()
    motion_t = seen[0]
    c.note(f"the simulator saw motion {1e3 * (motion_t - moving[0].t):.1f} ms after candump did")
    reference = [r["utime"] * 1e-6 - motion_t for r in rows]
    applied = {}
    for kind, offset in (("heartbeat-stop", HEARTBEAT_GAP[0]), ("heartbeat-resume", HEARTBEAT_GAP[1]),
                         ("heartbeat-disabled", HEARTBEAT_DISABLED[0]), ("heartbeat-enabled", HEARTBEAT_DISABLED[1]),
                         ("silent", SILENT[0]), ("state-resume", SILENT[1]), ("disable", DISABLE_AT)):
        hits = [t - motion_t for t, text in events if text.startswith(f"fault {kind} ")]
        late = hits[0] - offset if hits else float("nan")
        stall = stall_near(reference, offset)
        c.check(len(hits) == 1 and -0.002 <= late <= 0.02 + stall,
                f"fault {kind} applied once, {late * 1e3:.1f} ms after motion+{offset} s (limit 20 ms + guest stall {stall * 1e3:.0f} ms)")
        applied[kind] = hits[0] if hits else offset

    # Heartbeat: every 20 ms, enabled + watchdog (0x12, docs/can-protocol.md) except in the disabled window, and a gap.
    beats = [f for f in frames if f.extended and f.id == hil.HEARTBEAT_ID]
    c.check(all(len(f.data) == 8 for f in beats), f"{len(beats)} heartbeats, all 8 bytes")
    periods = [b.t - a.t for a, b in zip(beats, beats[1:])]
    c.check(abs(statistics.median(periods) - 0.020) < 0.002,
            f"heartbeat period median {statistics.median(periods) * 1e3:.2f} ms (20 ms)")
    reference = [r["utime"] * 1e-6 - motion_t for r in rows]
    c.check(silent_window(c, "heartbeat", [f.t - motion_t for f in beats],
                          (applied["heartbeat-stop"], applied["heartbeat-resume"]), reference),
            "no heartbeat between heartbeat-stop and heartbeat-resume, heartbeats right before and after")
    off = [f.t - motion_t for f in beats if f.data[4] != 0x12]
    on_inside = [f.t - motion_t for f in beats if f.data[4] == 0x12 and
                 applied["heartbeat-disabled"] + 0.002 < f.t - motion_t < applied["heartbeat-enabled"] - 0.002]
    c.check(all(f.data[4] in (0x12, 0x00) for f in beats) and off and not on_inside and
            applied["heartbeat-disabled"] <= min(off) and max(off) <= applied["heartbeat-enabled"] + 0.002,
            f"{len(off)} heartbeats without the enabled/watchdog bits, all between heartbeat-disabled and -enabled")
    c.check(summary["heartbeats"] == len(beats), f"simulator sent {summary['heartbeats']:.0f} heartbeats, capture has {len(beats)}")

    # Broadcast disable: exactly one, extended id 0, no data, when scheduled.
    disables = [f for f in frames if f.id == 0]
    c.check(len(disables) == 1 and disables[0].extended and disables[0].data == b"" and
            abs(disables[0].t - motion_t - applied["disable"]) < 0.005,
            f"one broadcast disable 00000000#, when the simulator applied the fault")

    # ARM_STATE: 100 Hz, silent for the scheduled window, pieces as given (none).
    state_t = [s["utime"] * 1e-6 for s in states]
    state_periods = [b - a for a, b in zip(state_t, state_t[1:])]
    c.check(states and abs(statistics.median(state_periods) - 0.010) < 0.001,
            f"{len(states)} ARM_STATE messages, period median {statistics.median(state_periods) * 1e3:.2f} ms (10 ms)")
    silent = (applied["silent"], applied["state-resume"])
    c.check(silent_window(c, "ARM_STATE", [t - motion_t for t in state_t], silent, reference),
            "no ARM_STATE between silent and state-resume, messages right before and after")
    published = [r["utime"] * 1e-6 - motion_t for r in rows if r["state_published"]]
    c.check(silent_window(c, "simulator CSV, published", published, silent, reference),
            "the simulator's CSV shows the same silent window")
    c.check(not any(s["pieces"] for s in states), "ARM_STATE reports no held pieces")
    c.check(summary["states_published"] >= len(states) > 0, "every logged ARM_STATE was counted as published")

    # Tracking: the simulated elevator follows the replayed move (the plant's own CSV). Judged on
    # frames canplayer delivered on time (the 60 ms before them at 5 +- 2 ms periods): after a
    # stall of the emulated guest a burst of late frames makes the command jump, which says nothing
    # about the plant.
    on_time = [f for i, f in enumerate(elevator_sp) if i > 0 and regular_before(elevator_sp, i, 0.06)
               and rows[0]["utime"] <= f.t * 1e6 <= rows[-1]["utime"]]
    # A stall of the guest shifts the plant's CSV time against the capture's, and the simulated
    # controller then takes up to ~0.1 s to pull back the error the stall left (after a 65 ms stall:
    # 3.5 mm 76 ms later, 0.9 mm 97 ms later): the bound allows the setpoint's speed times the
    # longest stall of the 150 ms before.
    row_t = [r["utime"] * 1e-6 for r in rows]

    def allowance(f):
        gap = hil.longest_gap(row_t, f.t - 0.15, f.t + 0.01)
        return abs(hil.decode_setpoint(f)[1]) * (max(gap - 0.010, 0.0) if gap == gap else 0.0)

    errors = [abs(interpolate(rows, ELEVATOR["q"], f.t * 1e6) - hil.decode_setpoint(f)[0]) for f in on_time]
    excess = [e - 0.003 - allowance(f) for e, f in zip(errors, on_time)]
    c.note(f"{len(on_time)} of {len(elevator_sp)} elevator setpoints were replayed on time")
    if len(on_time) >= 10:
        c.check(max(excess) < 0.0, f"elevator tracks the on-time setpoints: max error {max(errors) * 1e3:.2f} mm, "
                                   f"p50 {hil.percentile(errors, 50) * 1e3:.2f} mm (< 3 mm + speed x guest stall)")
    else:
        c.note("too few setpoints replayed on time to judge tracking against the capture")
    # The simulator's own view, whatever the replay's timing: the plant against the command its
    # controller tracked, row by row during the move.
    t_move = (moving[0].t * 1e6, moving[-1].t * 1e6)
    lag = [abs(r[ELEVATOR["q"]] - r[ELEVATOR["cmd_q"]]) for r in rows
           if t_move[0] <= r["utime"] <= t_move[1] and r[ELEVATOR["cmd_q"]] is not None]
    c.check(lag and hil.percentile(lag, 50) < 0.002,
            f"the plant follows its controller's command during the move: p50 {hil.percentile(lag, 50) * 1e3:.2f} mm, "
            f"p90 {hil.percentile(lag, 90) * 1e3:.2f} mm (p50 < 2 mm)")
    last = elevator_sp[-1].t * 1e6
    final_e = interpolate(rows, ELEVATOR["q"], last)
    final_a = interpolate(rows, ARM["q"], last)
    c.check(abs(final_e - ELEVATOR_TO) <= 0.001 and abs(final_a - ARM_AT) <= 0.0026,
            f"at the last setpoint: elevator {final_e:.5f} m (target {ELEVATOR_TO}), arm {final_a:.5f} rad (target {ARM_AT})")

    # After the stream ends the controllers go neutral and the elevator slides in brake mode.
    elevator = drive("elevator")
    slide = -(elevator["kG_volts"] - elevator["kS_volts"]) / elevator["kV"]
    end = rows[-1]
    c.check(end[ELEVATOR["cmd_q"]] is None and end[ELEVATOR["volts"]] == 0.0 and abs(end[ELEVATOR["v"]] - slide) < 0.02 * abs(slide),
            f"neutral at the end: 0 V, elevator sliding at {end[ELEVATOR['v']]:.4f} m/s (brake mode {slide:.4f})")
    c.check(abs(end[ARM["q"]] - ARM_AT) < 0.003, f"arm near vertical stays put in neutral ({end[ARM['q']]:.4f} rad)")

    # Counters: every replayed setpoint in order, the malformed ones counted.
    c.check(summary["setpoints_joint0"] == len(elevator_sp) and summary["setpoints_joint1"] == len(arm_sp),
            f"simulator took {summary['setpoints_joint0']:.0f}/{summary['setpoints_joint1']:.0f} setpoints")
    c.check(summary["sequence_gaps"] == 0, "no sequence gaps")
    c.check(summary["malformed"] == MALFORMED_SENT, f"malformed frames counted: {summary['malformed']:.0f} (sent {MALFORMED_SENT})")
    c.check(summary["motions"] == 1, f"one motion seen ({summary['motions']:.0f})")
    c.note(f"the simulator stood still {summary['freezes']:.0f} times, {summary['frozen_s'] * 1e3:.0f} ms in all")
    c.check(summary["other"] == 0 and summary["write_failures"] == 0 and summary["publish_failures"] == 0,
            "no other frames past the filter, no write or publish failures")
    return c.status()


def main(argv):
    if len(argv) == 3 and argv[1] == "setpoints":
        write_setpoints(argv[2])
        return 0
    if len(argv) == 3 and argv[1] == "check":
        return check(argv[2])
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
