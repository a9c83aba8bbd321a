#!/usr/bin/env python3
"""Host side of hil.daemon_three_joints: checks what tests/hil/daemon_three_joints.sh recorded in
the guest, for a robot with any number of joints (its robot.toml, as the guest ran it).

  three_joint_check.py OUT_DIR CONFIG

For each named move (the script notes move=ID:POSE:PIECES, and done=REQUEST for the request that
ended it): cyber-goal saw it done; every setpoint the daemon streamed while it executed lies on
its ARM_TRAJECTORY (each joint at the best-matching time within [-15, +5] ms of the capture, as
daemon_check.py's check_on_trajectories); the simulated mechanism tracked the setpoints (every
plant.csv row while moving, within the tolerance plus the commanded speed times the time the guest
had stood still since the move began: the setpoints went on meanwhile, the simulation not); and
0.2 s after the move it is within 5 mm (prismatic) or 10 mrad (revolute) of the pose. Then the protocol: every joint's setpoint stream at the daemon's rate
with its sequence +1 per frame and its feedforward within the drive's voltage limit, and the
simulator counted the same setpoints and no malformed frames.
"""

import bisect
import os
import statistics
import sys
import tomllib

# Frames the daemon may send after the simulator stops (0.2 s at 200 Hz).
kStopGapFrames = 40

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hil_lib as hil  # noqa: E402

STATUS = dict(accepted=0, planning=1, executing=2, done=3, rejected=4, failed=5, cancelled=6)
FINAL_TOLERANCE = {"prismatic": 0.005, "revolute": 0.010}  # as daemon_check.py: 5 mm, 10 mrad
# A setpoint on its trajectory: linear interpolation between 10 ms samples plus the frame's
# quantisation (docs/can-protocol.md) stays within these at the joints' speeds here.
ON_TRAJECTORY_TOLERANCE = {"prismatic": 0.003, "revolute": 0.006}
# How far the simulated joint may lag its setpoint while moving: the simulator's controllers
# follow the feedforward with a position loop (docs/testing.md, "Plant simulator").
TRACKING_TOLERANCE = {"prismatic": 0.02, "revolute": 0.05}
SETTLE_S = 0.2
# The simulator's log period (100 Hz rows).
ROW_PERIOD_S = 0.010


def stood_still_s(a, b, columns):
    """How long the emulated guest stood still between simulator rows a and b: the interval beyond
    the log period, or all of it when the simulation left it out (no joint moved, though one had a
    velocity: cyber-plant-sim's freeze clock, docs/testing.md "Plant simulator"). The daemon's
    setpoints went on meanwhile, so the simulated joint may lag them by the distance they moved."""
    gap = (b["utime"] - a["utime"]) * 1e-6
    frozen = all(a[c["q"]] == b[c["q"]] for c in columns) and any(abs(a[c["v"]] or 0.0) > 1e-9 for c in columns)
    return gap if frozen else max(gap - ROW_PERIOD_S, 0.0)


def main(argv):
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    out, config_path = argv[1], argv[2]
    with open(config_path, "rb") as f:
        config = tomllib.load(f)
    joints = config["joints"]
    n = len(joints)
    daemon = config.get("daemon", {})
    devices = {**{j["name"]: i + 1 for i, j in enumerate(joints)}, **daemon.get("devices", {})}
    period_s = 1.0 / daemon.get("stream_rate_hz", 200.0)
    columns = hil.plant_columns(config)
    c = hil.Checks("three_joint_check")

    frames = hil.read_candump(os.path.join(out, "bus.log"))
    events = hil.read_lcm_log(os.path.join(out, "lcm.log"))
    rows = hil.read_plant_csv(os.path.join(out, "plant.csv"))
    row_utime = [r["utime"] for r in rows]
    summary = hil.plant_summary(os.path.join(out, "plant_sim.err"))
    scenario = hil.read_scenario(os.path.join(out, "scenario.txt"))
    statuses = [hil.decode_plan_status(d) for _, ch, d in events if ch == "ARM_PLAN_STATUS"]
    trajectories = {}
    for _, ch, d in events:
        if ch == "ARM_TRAJECTORY":
            t = hil.decode_trajectory(d)
            trajectories[t["request_id"]] = t
    setpoints = []  # per joint: [(t, position, velocity, volts, sequence)]
    for j in joints:
        sid = hil.setpoint_id(devices[j["name"]])
        setpoints.append([(f.t,) + hil.decode_setpoint(f) for f in frames
                          if f.extended and f.id == sid and len(f.data) == 8 and not f.remote])

    def plant_row(t):
        return rows[max(bisect.bisect_right(row_utime, t * 1e6) - 1, 0)]

    moves = [m.split(":") for m in scenario.get("move", [])]
    done = [int(x) for x in scenario.get("done", [])]
    c.check(len(moves) >= 2 and len(done) == len(moves), f"{len(done)} of {len(moves)} named moves done")
    c.check(summary["joints"] == n, f"the simulator ran {summary['joints']:.0f} joints, the config has {n}")
    worst_on = [0.0] * n
    worst_track = [0.0] * n
    for move_id, pose, pieces in moves:
        request = next((r for r in done if r % 100 == int(move_id)), None)
        label = f"move {move_id} (-> {pose}, {pieces})"
        if not c.check(request is not None, f"{label} ended done"):
            continue
        final = hil.final_from_goal_output(os.path.join(out, f"goal{request}.out"), request, STATUS)
        c.check(final is not None and final["status"] == STATUS["done"], f"{label}: cyber-goal saw request {request} done")
        traj = trajectories.get(request)
        done_times = [s["utime"] * 1e-6 for s in statuses if s["request_id"] == request and s["status"] == STATUS["done"]]
        if not c.check(traj is not None and done_times, f"{label}: ARM_TRAJECTORY and its done status recorded"):
            continue
        start, duration, ts = traj["start_utime"] * 1e-6, traj["duration_s"], traj["t_s"]
        qs = traj["position"]

        def planned(j, tau):
            tau = min(max(tau, 0.0), ts[-1])
            i = min(max(bisect.bisect_right(ts, tau) - 1, 0), len(ts) - 2)
            w = (tau - ts[i]) / (ts[i + 1] - ts[i])
            return qs[j][i] + w * (qs[j][i + 1] - qs[j][i])

        off = 0
        count = 0
        for j, joint in enumerate(joints):
            for s in setpoints[j]:
                if not start <= s[0] <= start + duration:
                    continue
                count += 1
                err = min(abs(planned(j, s[0] - start - lag * 1e-3) - s[1]) for lag in range(-5, 16))
                worst_on[j] = max(worst_on[j], err)
                off += err > ON_TRAJECTORY_TOLERANCE[joint["type"]]
        c.check(count > 0 and off == 0, f"{label}: {count - off} of {count} setpoints on the planned trajectory "
                                       f"({duration:.3f} s)")
        first = bisect.bisect_left(row_utime, start * 1e6)
        last = bisect.bisect_right(row_utime, (start + duration) * 1e6)
        moving = rows[first:last]
        # Since the move began (from the row before it), how long the guest had stood still at
        # each moving row.
        stood = []
        total = 0.0
        for k in range(first, last):
            total += stood_still_s(rows[k - 1], rows[k], columns) if k > 0 else 0.0
            stood.append(total)
        for j, joint in enumerate(joints):
            col = columns[j]
            tolerance = TRACKING_TOLERANCE[joint["type"]]
            lag, excess, speed = 0.0, float("-inf"), 0.0
            for r, still in zip(moving, stood):
                if r[col["cmd_q"]] is None:
                    continue
                speed = max(speed, abs(r[col["cmd_v"]] or 0.0))
                this_lag = abs(r[col["q"]] - r[col["cmd_q"]])
                lag = max(lag, this_lag)
                excess = max(excess, this_lag - (tolerance + speed * still))
            worst_track[j] = max(worst_track[j], lag)
            c.check(moving and excess <= 0.0,
                    f"{label}: {joint['name']} tracked its setpoints within {lag:.4f} (<= {tolerance} + its commanded "
                    f"speed x the time the guest had stood still, {stood[-1] if stood else 0.0:.3f} s in all; "
                    f"worst margin {-excess:.4f}) over {len(moving)} rows")
        target = config["poses"][pieces.replace(",", "+")][pose]
        row = plant_row(done_times[0] + SETTLE_S)
        for j, joint in enumerate(joints):
            err = abs(row[columns[j]["q"]] - float(target[j]))
            c.check(err <= FINAL_TOLERANCE[joint["type"]],
                    f"{label}: {joint['name']} {err * 1e3:.2f} m{'m' if joint['type'] == 'prismatic' else 'rad'} "
                    f"from the pose {SETTLE_S} s after done")
    c.note("worst setpoint off its trajectory: " + ", ".join(f"{j['name']} {w * 1e3:.2f}" for j, w in zip(joints, worst_on))
           + " (mm or mrad); worst tracking lag: " + ", ".join(f"{j['name']} {w * 1e3:.1f}" for j, w in zip(joints, worst_track)))

    for j, joint in enumerate(joints):
        name = joint["name"]
        seq = [s[4] for s in setpoints[j]]
        jumps = [(b - a) % 256 for a, b in zip(seq, seq[1:]) if (b - a) % 256 != 1]
        c.check(len(seq) > 200 and not jumps, f"{name}: {len(seq)} setpoints, sequence +1 per frame (jumps {jumps[:5]})")
        periods = [b[0] - a[0] for a, b in zip(setpoints[j], setpoints[j][1:])]
        median = statistics.median(periods) if periods else float("nan")
        c.check(abs(median - period_s) <= 0.001, f"{name}: median period {median * 1e3:.2f} ms ({period_s * 1e3:.0f} ms)")
        limit = config["drives"][name]["voltage_limit_volts"]
        worst = max((abs(s[3]) for s in setpoints[j]), default=0.0)
        c.check(worst <= limit + 1e-9, f"{name}: feedforward within +-{limit} V (max |V| {worst:.3f})")
        # The run stops the simulator before the daemon: the capture may end with the frames sent in
        # between (12 at 200 Hz in the first run), never with fewer than the simulator took.
        taken = summary[f"setpoints_joint{j}"]
        c.check(0 <= len(seq) - taken <= kStopGapFrames,
                f"{name}: the simulator took {taken:.0f} setpoints, the capture has {len(seq)} "
                f"(at most {kStopGapFrames} more, sent after the simulator stopped)")
    c.check(summary["sequence_gaps"] == 0 and summary["malformed"] == 0,
            f"simulator: {summary['sequence_gaps']:.0f} sequence gaps, {summary['malformed']:.0f} malformed frames")
    return c.status()


if __name__ == "__main__":
    sys.exit(main(sys.argv))
