package cyberplanner.roborio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import cyberplanner.roborio.SetpointGuard.Verdict;
import cyberplanner.roborio.can.DaemonMode;
import cyberplanner.roborio.can.Setpoint;
import java.util.Random;
import org.junit.jupiter.api.Test;

class SetpointGuardTest {
  static final long MS = 1000;

  static Setpoint at(double position, int sequence) {
    return new Setpoint(1, position, 0.0, 0.5, sequence);
  }

  static SetpointGuard streaming(long nowMicros) {
    SetpointGuard guard = new SetpointGuard(0.05, 0.25);
    guard.onStatus(DaemonMode.HOLDING, nowMicros);
    guard.onSetpoint(Joint.JOINT_0, at(0.2, 10), nowMicros);
    guard.onSetpoint(Joint.JOINT_1, at(1.57, 200), nowMicros);
    return guard;
  }

  @Test
  void nothingHeardIsALostDaemon() {
    assertEquals(Verdict.DAEMON_LOST, new SetpointGuard(0.05, 0.25).verdict(0));
  }

  @Test
  void freshSetpointsOfAStreamingDaemonAreUsed() {
    SetpointGuard guard = streaming(1_000 * MS);
    assertEquals(Verdict.USE, guard.verdict(1_000 * MS));
    assertEquals(Verdict.USE, guard.verdict(1_050 * MS));  // the limit itself is still fresh
    assertEquals(0.2, guard.latest(Joint.JOINT_0).position());
  }

  @Test
  void aSetpointOlderThanItsLimitIsStale() {
    SetpointGuard guard = streaming(1_000 * MS);
    assertEquals(Verdict.SETPOINT_STALE, guard.verdict(1_051 * MS));
  }

  @Test
  void oneJointWithoutSetpointsIsStale() {
    SetpointGuard guard = new SetpointGuard(0.05, 0.25);
    guard.onStatus(DaemonMode.MOVING, 0);
    guard.onSetpoint(Joint.JOINT_0, at(0.2, 0), 0);
    assertEquals(Verdict.SETPOINT_STALE, guard.verdict(0));
  }

  @Test
  void aSilentDaemonIsLostEvenWithFreshSetpoints() {
    SetpointGuard guard = streaming(0);
    guard.onSetpoint(Joint.JOINT_0, at(0.2, 11), 260 * MS);
    guard.onSetpoint(Joint.JOINT_1, at(1.57, 201), 260 * MS);
    assertEquals(Verdict.DAEMON_LOST, guard.verdict(260 * MS));
  }

  @Test
  void noStateFaultAndDisabledModesDoNotStream() {
    for (DaemonMode mode : new DaemonMode[] {DaemonMode.NO_STATE, DaemonMode.FAULT, DaemonMode.ROBOT_DISABLED}) {
      SetpointGuard guard = streaming(0);
      guard.onStatus(mode, 0);
      assertEquals(Verdict.DAEMON_NOT_STREAMING, guard.verdict(0), mode.name());
    }
  }

  @Test
  void repeatsAreIgnoredAndGapsCountedAcrossTheWrap() {
    SetpointGuard guard = streaming(0);
    assertFalse(guard.onSetpoint(Joint.JOINT_1, at(9.0, 200), 10 * MS));  // a repeat: not fresh
    assertEquals(1.57, guard.latest(Joint.JOINT_1).position());
    assertEquals(Verdict.SETPOINT_STALE, guard.verdict(51 * MS));
    assertTrue(guard.onSetpoint(Joint.JOINT_1, at(1.6, 203), 20 * MS));  // 201, 202 lost
    assertTrue(guard.onSetpoint(Joint.JOINT_1, at(1.6, 1), 25 * MS));    // 204..255, 0 lost: 53
    assertEquals(2 + 53, guard.lostFrames(Joint.JOINT_1));
    assertEquals(1, guard.repeatedFrames(Joint.JOINT_1));
    assertEquals(0, guard.lostFrames(Joint.JOINT_0));
  }

  @Test
  void lostFramesMatchABruteForceCountOfSeededRandomDrops() {
    Random random = new Random(12);
    SetpointGuard guard = new SetpointGuard(0.05, 0.25);
    long pending = 0;
    long revealed = 0;  // drops followed by a received frame: the ones a sequence can show
    for (int sent = 0; sent < 5000; ++sent) {
      if (sent > 0 && random.nextInt(10) == 0) {
        pending++;
        continue;
      }
      revealed += pending;
      pending = 0;
      guard.onSetpoint(Joint.JOINT_0, at(0.0, sent & 0xFF), sent);
    }
    // Runs of 256 or more drops would alias; with p = 0.1 there are none.
    assertEquals(revealed, guard.lostFrames(Joint.JOINT_0));
    assertTrue(revealed > 400, "the seed drops about 10 %");
  }

  @Test
  void ageLimitsMustBePositive() {
    org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class, () -> new SetpointGuard(0, 1));
    org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class, () -> new SetpointGuard(1, Double.NaN));
  }
}
