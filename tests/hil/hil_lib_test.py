"""hil_lib's wire readers against the project's one definition of each format: the CAN setpoint
decoder and encoder against the shared vectors (tests/vectors/can_frames.txt, which the C++ codec
and the Java decoder also pass), the LCM fingerprints against the ones lcm-gen generated, and a
message the C++ LCM encoder wrote.
usage: hil_lib_test.py GENERATED_CPP_DIR WRITE_TRAJECTORY_LOG"""

import os
import re
import sys
import struct
import subprocess
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hil_lib as hil  # noqa: E402

# The generated C++ headers, then the command of the C++ encoder (an emulator first in a cross build).
GENERATED, WRITE_LOG = sys.argv[1], sys.argv[2:]


def vector_lines(kind):
    """(inputs, outputs) token lists of the shared vectors of one kind, error cases left out."""
    path = os.path.join(hil.SOURCE_DIR, "tests", "vectors", "can_frames.txt")
    with open(path) as f:
        lines = f.readlines()
    for line in lines:
        tokens = line.split()
        if tokens and tokens[0] == kind and "error" not in tokens:
            arrow = tokens.index("->")
            yield tokens[1:arrow], tokens[arrow + 1:]


def frame_of(text):
    ident, _, payload = text.partition("#")
    return hil.Frame(0.0, "can0", int(ident, 16), len(ident) == 8, False, bytes.fromhex(payload))


class CanFrames(unittest.TestCase):
    def test_decoder_matches_the_shared_vectors(self):
        cases = list(vector_lines("decode-setpoint"))
        self.assertGreater(len(cases), 5)
        for (frame_text,), (device, position, velocity, millivolts, sequence) in cases:
            frame = frame_of(frame_text)
            self.assertEqual(frame.id, hil.setpoint_id(int(device)), frame_text)
            self.assertEqual(hil.decode_setpoint(frame),
                             (int(position) / 1e5, int(velocity) / 1e3, int(millivolts) / 1e3, int(sequence)), frame_text)

    def test_encoder_matches_the_shared_vectors(self):
        cases = [(i, o) for i, o in vector_lines("encode-setpoint")
                 if all(re.fullmatch(r"-?[0-9.]+", x) for x in i)]  # finite decimal inputs
        self.assertGreater(len(cases), 5)
        for (device, position, velocity, volts, sequence), (frame_text,) in cases:
            frame = frame_of(frame_text)
            self.assertEqual(frame.id, hil.setpoint_id(int(device)), frame_text)
            self.assertEqual(hil.encode_setpoint(float(position), float(velocity), float(volts), int(sequence)),
                             frame.data, frame_text)

    def test_ids_come_from_the_codec_headers(self):
        self.assertEqual(hil.HEARTBEAT_ID, 0x01011840)
        self.assertEqual(hil.setpoint_id(1), 0x0A080401)
        self.assertEqual(hil.status_id(3), 0x0A080803)


class LcmMessages(unittest.TestCase):
    def test_fingerprints_are_lcm_gens(self):
        types = sorted(f[:-4] for f in os.listdir(os.path.join(hil.SOURCE_DIR, "lcmtypes")) if f.endswith(".lcm"))
        self.assertGreaterEqual(len(types), 6)
        for name in types:
            with open(os.path.join(GENERATED, "cyberplanner", name + ".hpp")) as f:
                generated = f.read()
            base = int(re.search(r"uint64_t hash = (0x[0-9a-f]+)LL", generated).group(1), 16)
            rotated = ((base << 1) & ((1 << 64) - 1)) | (base >> 63)
            self.assertEqual(hil.lcm_fingerprint(hil.lcm_members(name)), rotated, name)

    def test_decodes_what_the_cpp_encoder_wrote_and_refuses_another_fingerprint(self):
        with tempfile.TemporaryDirectory() as tmp:
            log = os.path.join(tmp, "t.lcm")
            subprocess.run([*WRITE_LOG, log], check=True)
            events = [d for _, ch, d in hil.read_lcm_log(log) if ch == "ARM_TRAJECTORY"]
        self.assertEqual(len(events), 2)  # 7 garbage bytes, then the message
        with self.assertRaisesRegex(ValueError, "truncated"):
            hil.decode_trajectory(events[0])
        t = hil.decode_trajectory(events[1])
        self.assertEqual((t["request_id"], t["num_samples"], len(t["volts"]), len(t["volts"][1])), (42, 101, 2, 101))
        self.assertEqual(t["num_joints"], 2)
        self.assertAlmostEqual(t["t_s"][100], 1.0)
        self.assertAlmostEqual(t["position"][0][100], 1.2)
        self.assertAlmostEqual(t["position"][1][100], 3.57)
        with self.assertRaisesRegex(ValueError, "fingerprint"):
            hil.decode_arm_state(events[1])
        with self.assertRaisesRegex(ValueError, "bytes after"):
            hil.decode_trajectory(events[1] + b"\0")


    def test_rows_follow_num_joints_even_without_samples(self):
        # arm_trajectory_t of 3 joints and 0 samples: 3 empty rows, as lcm-gen's nested vectors.
        fingerprint = hil.lcm_fingerprint(hil.lcm_members("arm_trajectory_t"))
        data = struct.pack(">Qqqqddbi", fingerprint, 1, 2, 3, 0.0, 0.01, 3, 0)
        t = hil.decode_trajectory(data)
        self.assertEqual((t["num_joints"], t["position"], t["volts"]), (3, [[], [], []], [[], [], []]))
        data = struct.pack(">Qqqqddbi", fingerprint, 1, 2, 3, 0.0, 0.01, 1, 2) + struct.pack(">8d", 0, 0.01, 1, 2, 2, 3, 0.5, 0.5)
        self.assertEqual(hil.decode_trajectory(data)["velocity"], [[2.0, 3.0]])


class Gaps(unittest.TestCase):
    def test_longest_gap_overlapping_the_window(self):
        times = [0.0, 0.01, 0.02, 0.1, 0.11, 0.5]
        self.assertAlmostEqual(hil.longest_gap(times, 0.0, 0.05), 0.08)
        self.assertAlmostEqual(hil.longest_gap(times, 0.105, 0.106), 0.01)
        self.assertAlmostEqual(hil.longest_gap(times, 0.2, 0.3), 0.39)
        self.assertEqual(hil.longest_gap([1.0], 0.0, 2.0, default=0.0), 0.0)


class FinalFromGoalOutput(unittest.TestCase):
    CODES = dict(accepted=0, planning=1, executing=2, done=3, rejected=4, failed=5, cancelled=6)

    def final(self, text, request_id=2):
        with tempfile.TemporaryDirectory() as out:
            path = os.path.join(out, "goal.out")
            with open(path, "w") as f:
                f.write(text)
            return hil.final_from_goal_output(path, request_id, self.CODES)

    # The fresh clone's goal2.out, whose final ARM_PLAN_STATUS lcm-logger missed.
    def test_the_final_line_with_its_reason(self):
        text = ("request 2 accepted\nrequest 2 planning\nrequest 2 trajectory: 834 samples, dt 0.0100 s, duration 8.325 s\n"
                "request 2 executing (duration 8.325 s, planned in 2193.8 ms)\n"
                "request 2 cancelled: superseded by request 3\n")
        self.assertEqual(self.final(text), {"request_id": 2, "status": 6, "reason": "superseded by request 3"})

    def test_no_final_line_or_another_request(self):
        self.assertIsNone(self.final("request 2 accepted\nrequest 2 executing (duration 1 s, planned in 1 ms)\n"))
        self.assertIsNone(self.final("request 12 done\n"))
        self.assertEqual(self.final("request 2 done\n")["status"], 3)


class PublishedAround(unittest.TestCase):
    # The simulator's rows at 100 Hz: published until 10.0 s, silent, published again from 10.5 s.
    ROWS = [{"utime": round(t * 1e6), "state_published": 0.0 if 10.0 < t < 10.5 else 1.0}
            for t in (9.97, 9.98, 9.99, 10.0, 10.1, 10.2, 10.3, 10.4, 10.5, 10.51)]

    def test_the_last_before_and_first_after_come_from_the_rows(self):
        # A recorder that missed 9.99 and 10.0 would have put the last state 20 ms earlier.
        self.assertEqual(hil.published_around(self.ROWS, 10.0004, 10.5), (10.0, 10.5))

    def test_unpublished_rows_do_not_count(self):
        self.assertEqual(hil.published_around(self.ROWS, 10.35, 10.05), (10.0, 10.5))


class HoldFit(unittest.TestCase):
    """daemon_check's hold_fit: a hold fits a logged state, or the newest one carried along its
    velocity across states the logger missed; an old command or a stale state does not fit."""

    @staticmethod
    def state(t_s, q0, q1, v0=0.0, v1=0.0):
        # An ARM_STATE as hil_lib decodes it: joints by index.
        return dict(utime=int(round(t_s * 1e6)), position=[q0, q1], velocity=[v0, v1], num_pieces=0, pieces=[])

    def setUp(self):
        sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
        import daemon_check
        self.dc = daemon_check
        # Sliding down at 0.6 m/s and 1.5 rad/s; the logger kept a state every 25 ms up to 10.0 s.
        self.states = [self.state(10.0 - 0.025 * k, 0.40 + 0.015 * k, 2.0 + 0.0375 * k, -0.6, -1.5) for k in range(6)]

    def fit(self, hold, t_s):
        return self.dc.hold_fit(hold, self.states, t_s, 0.15)

    def test_a_logged_state_fits(self):
        score, m, carried_s = self.fit((0.415, 2.0375), 10.01)
        self.assertLessEqual(score, 1.0)
        self.assertEqual((m["utime"], carried_s), (self.states[1]["utime"], 0.0))

    def test_the_newest_state_carried_across_a_logging_gap_fits(self):
        # The daemon held the plant 20 ms past the last logged state: 12 mm and 30 mrad further on.
        score, m, carried_s = self.fit((0.388, 1.970), 10.024)
        self.assertLessEqual(score, 1.0)
        self.assertEqual(m["utime"], self.states[0]["utime"])
        self.assertAlmostEqual(carried_s, 0.020, delta=0.002)

    def test_holds_off_the_line_or_beyond_the_carry_do_not_fit(self):
        self.assertGreater(self.fit((0.388 + 0.17, 1.970), 10.024)[0], 1.0)  # the last command
        self.assertGreater(self.fit((0.388, 2.0), 10.024)[0], 1.0)  # the joints from different times
        far_s = self.dc.MAX_CARRY_S + 0.02
        self.assertGreater(self.fit((0.40 - 0.6 * far_s, 2.0 - 1.5 * far_s), 10.0 + far_s)[0], 1.0)

    def test_no_state_in_the_window(self):
        self.assertEqual(self.fit((0.4, 2.0), 11.0)[1], None)


class StartShift(unittest.TestCase):
    """daemon_check's best_start_shift finds how far a captured motion runs ahead of its
    ARM_TRAJECTORY's start_utime (the diagnosis printed when the ticks do not fit)."""

    def test_a_motion_35_ms_ahead_of_its_stamp(self):
        sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
        import daemon_check as dc
        # Constant acceleration 2 m/s^2 and 8 rad/s^2 for 0.5 s, sampled every 10 ms from 100 s.
        t = [0.01 * k for k in range(51)]
        msg = dict(start_utime=100_000_000, duration_s=0.5, t_s=t,
                   position=[[t_ * t_ for t_ in t], [4 * t_ * t_ for t_ in t]],
                   velocity=[[2 * t_ for t_ in t], [8 * t_ for t_ in t]], volts=[[0.0] * 51, [0.0] * 51])
        traj = dc.Trajectory(msg)
        ticks = []
        for k in range(1, 80):
            tau = 0.005 * k + 0.035
            ticks.append((100.0 + 0.005 * k, [traj.at(tau, 0)[:2] + (0.0,), traj.at(tau, 1)[:2] + (0.0,)]))
        shift, error = dc.best_start_shift(traj, ticks)
        self.assertAlmostEqual(shift, -0.035, delta=6e-4)
        self.assertLess(error, 1e-4)


def daemon_log(minute, lines):
    """cyber-plannerd log lines ("SS.mmm level text") stamped within one minute of 2026-12-02."""
    return "".join(f"2026-12-02 {minute}:{line}\n" for line in lines)


def judge_results(verdict, files):
    """daemon_check.<verdict>(out) on a results directory holding `files` ({name: text})."""
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import daemon_check
    with tempfile.TemporaryDirectory() as out:
        for name, text in files.items():
            with open(os.path.join(out, name), "w") as f:
                f.write(text)
        return getattr(daemon_check, verdict)(out)


class SpliceVoid(unittest.TestCase):
    """daemon_check's splice_outlasted: a motion run is void when goal 2 ended while goal 3 was
    still being planned, not when goal 2 had ended before goal 3's planning began."""

    def outlasted(self, lines):
        return judge_results("splice_outlasted", {"daemon.log": daemon_log("13:12", lines)})

    def test_goal_2_ending_while_goal_3_is_planned_is_void(self):
        self.assertTrue(self.outlasted(["08.761 info request 2 executing (4.163 s, planned in 21340.6 ms)",
                                        "12.917 info request 2 done",
                                        "12.922 info request 3 executing (0.987 s, planned in 2089.5 ms)"]))

    def test_a_plan_past_its_splice_point_is_void(self):
        self.assertTrue(self.outlasted(["08.761 info request 2 executing (4.163 s, planned in 21340.6 ms)",
                                        "11.000 warning request 3: plan took 3874.1 ms, missing its splice point",
                                        "12.917 info request 2 done",
                                        "13.800 info request 3 executing (0.987 s, planned in 850.7 ms)"]))

    def test_goal_3_planned_only_after_goal_2_ended_is_not_void(self):
        self.assertFalse(self.outlasted(["08.761 info request 2 executing (4.163 s, planned in 21340.6 ms)",
                                         "12.917 info request 2 done",
                                         "14.000 info request 3 executing (0.987 s, planned in 900.0 ms)"]))

    def test_a_splice_is_not_void(self):
        self.assertFalse(self.outlasted(["08.761 info request 2 executing (4.163 s, planned in 21340.6 ms)",
                                         "11.500 info request 3 executing (0.987 s, planned in 2089.5 ms)",
                                         "11.501 info request 2 cancelled: replaced by request 3"]))


class LinkVoid(unittest.TestCase):
    """daemon_check's link_outlasted: a link run is void when its goal was done before the link
    went down (the guest stood still after the simulator said "moving"), not when the outage cut
    the move."""

    def outlasted(self, lines, scenario="emulated=1\nlink=1\n"):
        return judge_results("link_outlasted", {"daemon.log": daemon_log("14:23", lines), "scenario.txt": scenario})

    # The fresh clone's run: done at 50.020, the link down at 50.338.
    def test_a_goal_done_before_the_link_went_down_is_void(self):
        self.assertTrue(self.outlasted(["47.071 info request 1 executing (3.268 s, planned in 9809.7 ms)",
                                        "50.020 info request 1 done",
                                        "50.338 warning CAN write failed: network down: Network is down"]))

    def test_an_outage_during_the_move_is_not_void(self):
        self.assertFalse(self.outlasted(["47.071 info request 1 executing (3.268 s, planned in 9809.7 ms)",
                                         "47.400 warning CAN write failed: network down: Network is down",
                                         "47.480 warning motion stopped: no fresh roboRIO heartbeat"]))

    # The final fresh clone's run: the simulator coasted the arm 15 mm into l4_post.
    def test_a_next_goal_refused_because_its_start_touches_an_obstacle_is_void(self):
        self.assertTrue(self.outlasted([
            "52.566 info request 1 executing (3.268 s, planned in 4380.6 ms)",
            "55.531 warning CAN write failed: network down: Network is down",
            "59.790 warning request 2 failed: start in collision: start (1.8470 m, 5.1135 rad) is -0.0149 m from "
            "l4_post (clearance 0.0300 m); it touches an obstacle, so no way out is planned"]))

    def test_another_goal_done_does_not_count(self):
        self.assertFalse(self.outlasted(["47.000 info request 1 done",
                                         "48.400 warning CAN write failed: network down: Network is down"],
                                        scenario="emulated=1\nretry=1\nlink=101\n"))


class StallVerdict(unittest.TestCase):
    """daemon_check.py stalled: a silence counts only once the simulator's heartbeat has begun."""

    def stalled(self, lines):
        with tempfile.TemporaryDirectory() as out:
            with open(os.path.join(out, "bus.log"), "w") as f:
                f.write("".join(line + "\n" for line in lines))
            checker = os.path.join(os.path.dirname(os.path.abspath(__file__)), "daemon_check.py")
            run = subprocess.run([sys.executable, checker, "stalled", out, "0.5"], capture_output=True, text=True)
            self.assertIn(run.returncode, (0, 1), run.stderr)
            return run.returncode == 0

    def beats(self, t0, t1):
        return [f"({t0 + 0.02 * k:.6f}) vcan0 {hil.HEARTBEAT_ID:08X}#01" for k in range(int((t1 - t0) / 0.02) + 1)]

    def test_start_up_silence_before_the_first_heartbeat_is_not_a_stall(self):
        self.assertFalse(self.stalled(["(1.000000) vcan0 7FF#00"] + self.beats(1.9, 3.0)))

    def test_silence_after_the_heartbeat_began_is_a_stall(self):
        self.assertTrue(self.stalled(self.beats(1.0, 2.0) + self.beats(2.6, 3.0)))
        self.assertFalse(self.stalled(self.beats(1.0, 2.0) + self.beats(2.4, 3.0)))


class PlantReaders(unittest.TestCase):
    """plant_summary and plant_columns take as many joints as the config has (one to three)."""

    def summary(self, positions, setpoints):
        line = (f"12.345 info stopped: {positions}; setpoints {setpoints}, sequence gaps 0, malformed 2, other 0, "
                "bus errors 0, read failures 0; sent heartbeats 500, disables 0, write failures 0; ARM_STATE "
                "published 1000, failed 0; motions 3; frozen 1 times, 0.250 s\n")
        with tempfile.NamedTemporaryFile("w", suffix=".err", delete=False) as f:
            f.write("12.000 info started\n" + line)
        try:
            return hil.plant_summary(f.name)
        finally:
            os.unlink(f.name)

    def test_two_joints(self):
        s = self.summary("elevator 0.200000 m, arm 1.570000 rad", "elevator 812 arm 810")
        self.assertEqual((s["joints"], s["joint0"], s["joint1"]), (2, 0.2, 1.57))
        self.assertEqual((s["setpoints_joint0"], s["setpoints_joint1"]), (812, 810))
        self.assertNotIn("joint2", s)
        self.assertEqual((s["malformed"], s["heartbeats"], s["motions"], s["frozen_s"]), (2, 500, 3, 0.25))

    def test_three_joints(self):
        s = self.summary("elevator 0.050000 m, pivot 1.570800 rad, wrist -0.100000 rad", "elevator 5 pivot 6 wrist 7")
        self.assertEqual([s[f"joint{j}"] for j in range(3)], [0.05, 1.5708, -0.1])
        self.assertEqual([s[f"setpoints_joint{j}"] for j in range(3)], [5, 6, 7])
        self.assertEqual((s["joints"], s["states_published"], s["freezes"]), (3, 1000, 1))

    def test_one_joint_and_no_line(self):
        s = self.summary("lift 0.300000 m", "lift 9")
        self.assertEqual((s["joints"], s["joint0"], s["setpoints_joint0"]), (1, 0.3, 9))
        with tempfile.NamedTemporaryFile("w", suffix=".err") as f:
            f.write("nothing here\n")
            f.flush()
            with self.assertRaises(ValueError):
                hil.plant_summary(f.name)

    def test_columns_of_each_joint(self):
        config = {"joints": [{"name": "elevator", "type": "prismatic"}, {"name": "pivot", "type": "revolute"},
                             {"name": "wrist", "type": "revolute"}]}
        columns = hil.plant_columns(config)
        self.assertEqual([c["q"] for c in columns], ["elevator_m", "pivot_rad", "wrist_rad"])
        self.assertEqual(columns[2]["cmd_v"], "wrist_cmd_radps")


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
