package cyberplanner.roborio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import cyberplanner.roborio.SetpointGuard.Verdict;
import cyberplanner.roborio.can.DaemonMode;
import cyberplanner.roborio.can.Setpoint;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class SetpointGuardTest {
  static final long MS = 1000;
  static final JointChain TWO = JointChain.of("elevator", "arm");

  static Setpoint at(double position, int sequence) {
    return new Setpoint(1, position, 0.0, 0.5, sequence);
  }

  static SetpointGuard streaming(long nowMicros) {
    SetpointGuard guard = new SetpointGuard(TWO, 0.05, 0.25);
    guard.onStatus(DaemonMode.HOLDING, nowMicros);
    guard.onSetpoint(0, at(0.2, 10), nowMicros);
    guard.onSetpoint(1, at(1.57, 200), nowMicros);
    return guard;
  }

  @Test
  void nothingHeardIsALostDaemon() {
    assertEquals(Verdict.DAEMON_LOST, new SetpointGuard(TWO, 0.05, 0.25).verdict(0));
  }

  @Test
  void freshSetpointsOfAStreamingDaemonAreUsed() {
    SetpointGuard guard = streaming(1_000 * MS);
    assertEquals(Verdict.USE, guard.verdict(1_000 * MS));
    assertEquals(Verdict.USE, guard.verdict(1_050 * MS));  // the limit itself is still fresh
    assertEquals(0.2, guard.latest(0).position());
  }

  @Test
  void aSetpointOlderThanItsLimitIsStale() {
    SetpointGuard guard = streaming(1_000 * MS);
    assertEquals(Verdict.SETPOINT_STALE, guard.verdict(1_051 * MS));
  }

  @Test
  void oneJointWithoutSetpointsIsStale() {
    SetpointGuard guard = new SetpointGuard(TWO, 0.05, 0.25);
    guard.onStatus(DaemonMode.MOVING, 0);
    guard.onSetpoint(0, at(0.2, 0), 0);
    assertEquals(Verdict.SETPOINT_STALE, guard.verdict(0));
  }

  @Test
  void aSilentDaemonIsLostEvenWithFreshSetpoints() {
    SetpointGuard guard = streaming(0);
    guard.onSetpoint(0, at(0.2, 11), 260 * MS);
    guard.onSetpoint(1, at(1.57, 201), 260 * MS);
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
    assertFalse(guard.onSetpoint(1, at(9.0, 200), 10 * MS));  // a repeat: not fresh
    assertEquals(1.57, guard.latest(1).position());
    assertEquals(Verdict.SETPOINT_STALE, guard.verdict(51 * MS));
    assertTrue(guard.onSetpoint(1, at(1.6, 203), 20 * MS));  // 201, 202 lost
    assertTrue(guard.onSetpoint(1, at(1.6, 1), 25 * MS));    // 204..255, 0 lost: 53
    assertEquals(2 + 53, guard.lostFrames(1));
    assertEquals(1, guard.repeatedFrames(1));
    assertEquals(0, guard.lostFrames(0));
  }

  @Test
  void lostFramesMatchABruteForceCountOfSeededRandomDrops() {
    Random random = new Random(12);
    SetpointGuard guard = new SetpointGuard(TWO, 0.05, 0.25);
    long pending = 0;
    long revealed = 0;  // drops followed by a received frame: the ones a sequence can show
    for (int sent = 0; sent < 5000; ++sent) {
      if (sent > 0 && random.nextInt(10) == 0) {
        pending++;
        continue;
      }
      revealed += pending;
      pending = 0;
      guard.onSetpoint(0, at(0.0, sent & 0xFF), sent);
    }
    // Runs of 256 or more drops would alias; with p = 0.1 there are none.
    assertEquals(revealed, guard.lostFrames(0));
    assertTrue(revealed > 400, "the seed drops about 10 %");
  }

  @Test
  void ageLimitsMustBePositive() {
    assertThrows(IllegalArgumentException.class, () -> new SetpointGuard(TWO, 0, 1));
    assertThrows(IllegalArgumentException.class, () -> new SetpointGuard(TWO, 1, Double.NaN));
    assertThrows(IllegalArgumentException.class, () -> new SetpointGuard(null, 1, 1));
  }

  /** A guard of n joints that heard a streaming daemon and a setpoint of each joint at 0. */
  static SetpointGuard streamingChain(int n) {
    SetpointGuard guard = new SetpointGuard(JointChain.of(List.of("j0", "j1", "j2").subList(0, n)));
    guard.onStatus(DaemonMode.MOVING, 0);
    for (int i = 0; i < n; ++i) guard.onSetpoint(i, at(i + 0.5, 0), 0);
    return guard;
  }

  @ParameterizedTest
  @ValueSource(ints = {1, 2, 3})
  void everyJointOfTheChainMustBeFreshAndNoOtherIsOne(int n) {
    SetpointGuard guard = streamingChain(n);
    assertEquals(Verdict.USE, guard.verdict(0));
    for (int i = 0; i < n; ++i) assertEquals(i + 0.5, guard.latest(i).position());
    assertEquals(n - 0.5, guard.latest("j" + (n - 1)).position());
    // The last joint alone goes stale: the whole arm does.
    for (int i = 0; i < n - 1; ++i) guard.onSetpoint(i, at(0, 1), 40 * MS);
    assertEquals(Verdict.SETPOINT_STALE, guard.verdict(60 * MS));
    guard.onSetpoint(n - 1, at(0, 1), 40 * MS);
    assertEquals(Verdict.USE, guard.verdict(60 * MS));
    // An index past the chain is a wiring mistake, said at once.
    IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> guard.onSetpoint(n, at(0, 2), 0));
    assertTrue(e.getMessage().startsWith("no joint " + n + ": the joints are 0 j0"), e.getMessage());
    assertThrows(IllegalArgumentException.class, () -> guard.lostFrames("wrist"));
  }

  @Test
  void aDaemonWhoseJointsAreNotTheArmsIsNotFollowed() {
    SetpointGuard guard = streaming(0);
    guard.onDaemonJoints(List.of());  // unknown (no ARM_DAEMON_STATUS yet, CAN only): not checked
    assertEquals(Verdict.USE, guard.verdict(0));
    guard.onDaemonJoints(List.of("elevator", "arm"));
    assertEquals(Verdict.USE, guard.verdict(0));
    guard.onDaemonJoints(List.of("arm", "elevator"));  // wired in another order
    assertEquals(Verdict.JOINTS_MISMATCH, guard.verdict(0));
    guard.onDaemonJoints(List.of("shoulder", "elbow", "wrist"));  // another robot's daemon
    assertEquals(Verdict.JOINTS_MISMATCH, guard.verdict(0));
    guard.onStatus(DaemonMode.FAULT, 0);
    assertEquals(Verdict.DAEMON_NOT_STREAMING, guard.verdict(0), "the checks' order");
  }
}
