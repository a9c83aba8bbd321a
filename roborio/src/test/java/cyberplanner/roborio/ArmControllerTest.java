package cyberplanner.roborio;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import cyberplanner.arm_cancel_t;
import cyberplanner.arm_daemon_status_t;
import cyberplanner.arm_goal_t;
import cyberplanner.arm_plan_status_t;
import cyberplanner.roborio.can.DaemonMode;
import cyberplanner.roborio.can.Setpoint;
import java.util.ArrayList;
import java.util.List;
import lcm.lcm.LCM;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The robot loop without WPILib: what reaches the joints, and the values ArmInputs gives the loop
 * to log (docs/roborio.md, "Values to log").
 */
class ArmControllerTest {
  long nowMicros = 1_000_000;
  boolean enabled = true;
  final List<double[]> joint0Requests = new ArrayList<>();
  final List<double[]> joint1Requests = new ArrayList<>();
  final JointOutput joint0 = (p, v, ff) -> joint0Requests.add(new double[] {p, v, ff});
  final JointOutput joint1 = (p, v, ff) -> joint1Requests.add(new double[] {p, v, ff});
  /** A source that delivers one fresh pair of setpoints per loop, sequence counting up. */
  int sequence;
  DaemonMode mode = DaemonMode.MOVING;
  boolean daemonOnTheBus = true;
  ArmState measured = ArmState.of(0.3, 0, 1.5, 0).holding("coral");
  final SetpointSource source = (guard, now) -> {
    if (!daemonOnTheBus) return;
    guard.onStatus(mode, now);
    guard.onSetpoint(0, new Setpoint(1, 0.5, 0.1, 0.4, sequence & 0xFF), now);
    guard.onSetpoint(1, new Setpoint(2, 1.0, 0.0, 0.1, sequence & 0xFF), now);
    sequence += 2;  // every other frame lost
  };

  ArmController controller(LCM lcm) {
    CyberPlannerClient client = new CyberPlannerClient(lcm, Channels.DEFAULT, 9);
    return new ArmController(new ArmController.Parts(client, source,
        List.of(ArmJoint.of("elevator", joint0, JointGravity.constant(0.37)),
            ArmJoint.of("arm", joint1, JointGravity.cosine(0.21))),
        () -> measured, () -> enabled, () -> nowMicros));
  }

  @Test
  void inputsCarryTheLinkTheDaemonTheVerdictTheMoveAndTheCounters() throws Exception {
    LCM lcm = new LCM("memq://");
    ArmController controller = controller(lcm);
    ArmInputs inputs = new ArmInputs();
    controller.periodic();
    controller.updateInputs(inputs);
    assertTrue(inputs.linkConnected);
    assertEquals("", inputs.linkError);
    assertFalse(inputs.daemonAlive);
    assertEquals("USE", inputs.verdict);
    assertEquals(0, inputs.moveRequestId);
    assertEquals("", inputs.daemonJoints);

    lcm.publish("ARM_DAEMON_STATUS", ClientMemqTest.daemonStatus(arm_daemon_status_t.MODE_MOVING));
    MoveHandle move = controller.moveTo(Pose.of(1.22, 5.69));
    ClientMemqTest.status(lcm, 9, arm_plan_status_t.STATUS_EXECUTING, "");
    ClientMemqTest.until(() -> move.state() == MoveState.EXECUTING && controller.client().daemonMode() != null);
    controller.periodic();
    ClientMemqTest.status(lcm, 9, arm_plan_status_t.STATUS_DONE, "");
    move.await(2);
    controller.periodic();
    controller.updateInputs(inputs);
    assertTrue(inputs.daemonAlive);
    assertEquals("MOVING", inputs.daemonMode);
    assertEquals("elevator m, arm rad", inputs.daemonJoints);
    assertEquals(9, inputs.moveRequestId);
    assertEquals("DONE", inputs.moveState);
    assertEquals(0.5, inputs.moveDurationS);
    assertEquals(2, inputs.moveStateChanges);  // EXECUTING, then DONE, as the loop saw them
    assertArrayEquals(new String[] {"elevator", "arm"}, inputs.jointNames);
    assertArrayEquals(new long[] {2, 2}, inputs.lostFrames);  // one per loop after the first
    assertArrayEquals(new long[] {0, 0}, inputs.repeatedFrames);
    controller.client().close();
  }

  @Test
  void nothingIsAppliedWhileDisabledOrOverriddenAndAMoveEndsTheOverride() throws Exception {
    LCM lcm = new LCM("memq://");
    ArmController controller = controller(lcm);
    enabled = false;
    controller.periodic();
    assertEquals(0, joint0Requests.size());
    enabled = true;
    controller.periodic();
    assertEquals(1, joint0Requests.size());
    // Each joint's own setpoint reaches its own motor, with the setpoint's own feedforward.
    assertArrayEquals(new double[] {0.5, 0.1, 0.4}, joint0Requests.get(0));
    assertArrayEquals(new double[] {1.0, 0.0, 0.1}, joint1Requests.get(0));
    controller.beginManualOverride();
    controller.periodic();
    ArmInputs inputs = new ArmInputs();
    controller.updateInputs(inputs);
    assertTrue(inputs.manualOverride);
    assertEquals(1, joint0Requests.size());
    controller.moveTo(Pose.of(0.2, 1.57));
    assertFalse(controller.isManualOverride());
    controller.periodic();
    assertEquals(2, joint0Requests.size());
    mode = DaemonMode.RELEASED;  // not streaming: the hold, against each joint's own gravity model
    controller.periodic();
    assertArrayEquals(new double[] {0.3, 0.0, 0.37}, joint0Requests.get(2));
    assertArrayEquals(new double[] {1.5, 0.0, 0.21 * Math.cos(1.5)}, joint1Requests.get(2));
    controller.client().close();
  }

  void assertHolding(double joint0Position, double joint1Position) {
    assertArrayEquals(new double[] {joint0Position, 0.0, 0.37}, joint0Requests.get(joint0Requests.size() - 1));
    assertArrayEquals(new double[] {joint1Position, 0.0, 0.21 * Math.cos(joint1Position)},
        joint1Requests.get(joint1Requests.size() - 1));
  }

  @Test
  void theHoldIsCapturedAfreshAfterADisableAndAfterAManualOverride() throws Exception {
    // No daemon: the fallback holds. A disable or an override in between ends that hold, so the
    // next one is where the mechanism is then, not where the one before began.
    ArmController controller = controller(new LCM("memq://"));
    daemonOnTheBus = false;
    controller.periodic();
    assertEquals(SetpointGuard.Verdict.DAEMON_LOST, controller.verdict());
    assertHolding(0.3, 1.5);
    enabled = false;
    controller.periodic();
    measured = ArmState.of(0.25, 0, 1.4, 0);  // it sagged while disabled
    enabled = true;
    controller.periodic();
    assertHolding(0.25, 1.4);
    controller.beginManualOverride();
    controller.periodic();
    measured = ArmState.of(0.6, 0, 2.0, 0);  // the team's command drove it
    controller.endManualOverride();
    controller.periodic();
    assertHolding(0.6, 2.0);
    controller.client().close();
  }

  @Test
  void aMoveReplacedByAGoalIsNotCancelledAndOneWithoutASuccessorIsHeldNextLoop() throws Exception {
    LCM lcm = new LCM("memq://");
    List<arm_goal_t> goals = ClientMemqTest.collect(lcm, "ARM_GOAL", arm_goal_t::new);
    List<arm_cancel_t> cancels = ClientMemqTest.collect(lcm, "ARM_CANCEL", arm_cancel_t::new);
    ArmController controller = controller(lcm);
    MoveHandle first = controller.moveTo(Pose.of(0.78, 6.09));
    controller.periodic();
    // A command interrupted by one that sends a goal: the goal replaces the move.
    controller.cancelUnlessReplaced(first);
    MoveHandle second = controller.moveTo(Pose.of(1.27, 5.79));
    controller.periodic();
    // Interrupted by nothing that sends a goal: held at the next loop. Holds arrive in the order
    // they were sent, so one for the first move would come before.
    controller.cancelUnlessReplaced(second);
    controller.periodic();
    ClientMemqTest.until(() -> !cancels.isEmpty() && goals.size() == 2);
    assertEquals(second.requestId(), cancels.get(0).request_id, "the first cancel's request");
    assertEquals(arm_cancel_t.ACTION_HOLD, cancels.get(0).action);
    // A manual override's release ends every open goal: no hold after it.
    MoveHandle third = controller.moveTo(Pose.of(0.2, 1.57));
    controller.cancelUnlessReplaced(third);
    controller.beginManualOverride();
    controller.periodic();
    controller.endManualOverride();
    MoveHandle fourth = controller.moveTo(Pose.of(0.58, 2.97));
    controller.cancel(fourth);  // a cancel of the robot program's own: at once
    ClientMemqTest.until(() -> cancels.size() >= 3);
    assertEquals(-1, cancels.get(1).request_id);
    assertEquals(arm_cancel_t.ACTION_RELEASE, cancels.get(1).action);
    assertEquals(fourth.requestId(), cancels.get(2).request_id, "the cancel after the release");
    assertEquals(4, goals.size());
    controller.client().close();
  }

  /** An arm of n joints (1 to 3) on recorded outputs, fed by a source of one fresh setpoint per joint per loop. */
  static final class Chain {
    static final List<String> NAMES = List.of("shoulder", "elbow", "wrist");
    final int n;
    final JointChain joints;
    final List<List<double[]>> requests = new ArrayList<>();
    final List<ArmJoint> armJoints = new ArrayList<>();
    final List<Integer> fed = new ArrayList<>();  // the joint indices the source feeds
    DaemonMode mode = DaemonMode.MOVING;
    ArmState measured;
    int sequence;
    long nowMicros = 1_000_000;
    final ArmController controller;

    Chain(int n) throws Exception {
      this.n = n;
      joints = JointChain.of(NAMES.subList(0, n));
      double[] positions = new double[n];
      for (int i = 0; i < n; ++i) {
        List<double[]> mine = new ArrayList<>();
        requests.add(mine);
        // Joint i's gravity is (i + 1) * 0.1 V, constant: each hold says whose it is.
        armJoints.add(ArmJoint.of(NAMES.get(i), (p, v, ff) -> mine.add(new double[] {p, v, ff}),
            JointGravity.constant((i + 1) * 0.1)));
        positions[i] = 10 + i;
        fed.add(i);
      }
      measured = ArmState.of(positions, new double[n]);
      SetpointSource source = (guard, now) -> {
        guard.onStatus(mode, now);
        // Joint i's setpoint is (i, 0.1 i, -i V): each value says whose it is.
        for (int i : fed) guard.onSetpoint(i, new Setpoint(i + 1, i, 0.1 * i, -i, sequence & 0xFF), now);
        sequence++;
      };
      CyberPlannerClient client = new CyberPlannerClient(new LCM("memq://"), Channels.DEFAULT, 1);
      controller = new ArmController(new ArmController.Parts(client, source, armJoints, () -> measured, () -> true,
          () -> nowMicros));
    }

    double[] last(int joint) {
      List<double[]> mine = requests.get(joint);
      return mine.get(mine.size() - 1);
    }
  }

  @ParameterizedTest
  @ValueSource(ints = {1, 2, 3})
  void eachJointsSetpointReachesItsOwnOutputByIndex(int n) throws Exception {
    Chain arm = new Chain(n);
    arm.controller.periodic();
    assertEquals(SetpointGuard.Verdict.USE, arm.controller.verdict());
    for (int i = 0; i < n; ++i) {
      assertEquals(1, arm.requests.get(i).size(), "joint " + i);
      assertArrayEquals(new double[] {i, 0.1 * i, -i}, arm.last(i), "joint " + i);
    }
    assertEquals(arm.joints, arm.controller.joints());
    // The last joint's frames stop: no joint is driven by setpoints, all are held.
    arm.fed.remove(Integer.valueOf(n - 1));
    arm.nowMicros += 60_000;
    arm.controller.periodic();
    assertEquals(SetpointGuard.Verdict.SETPOINT_STALE, arm.controller.verdict());
    ArmInputs inputs = new ArmInputs();
    arm.controller.updateInputs(inputs);
    assertArrayEquals(arm.joints.names().toArray(new String[0]), inputs.jointNames);
    assertEquals(n, inputs.lostFrames.length);
    arm.controller.client().close();
  }

  @ParameterizedTest
  @ValueSource(ints = {1, 2, 3})
  void theHoldCapturesEveryJointWhereItIsAgainstItsOwnGravity(int n) throws Exception {
    Chain arm = new Chain(n);
    arm.controller.periodic();  // setpoints in use
    double[] at = new double[n];
    for (int i = 0; i < n; ++i) at[i] = -0.5 * i + 0.25;
    arm.measured = ArmState.of(at, new double[n]);
    arm.mode = DaemonMode.FAULT;
    arm.controller.periodic();
    assertEquals(SetpointGuard.Verdict.DAEMON_NOT_STREAMING, arm.controller.verdict());
    for (int i = 0; i < n; ++i) {
      assertArrayEquals(new double[] {at[i], 0.0, (i + 1) * 0.1}, arm.last(i), "joint " + i + " held");
    }
    // Within the unusable stretch the hold stays where it was captured, for every joint.
    arm.measured = ArmState.of(new double[n], new double[n]);
    arm.controller.periodic();
    for (int i = 0; i < n; ++i) assertEquals(at[i], arm.last(i)[0], "joint " + i + " still held");
    arm.controller.client().close();
  }

  @ParameterizedTest
  @ValueSource(ints = {1, 2, 3})
  void aPoseOfTheWrongLengthIsRefusedWithBothCountsAndSendsNothing(int n) throws Exception {
    LCM lcm = new LCM("memq://");
    List<arm_goal_t> goals = ClientMemqTest.collect(lcm, "ARM_GOAL", arm_goal_t::new);
    Chain arm = new Chain(n);
    ArmController controller = new ArmController(new ArmController.Parts(
        new CyberPlannerClient(lcm, Channels.DEFAULT, 1), (guard, now) -> {}, arm.armJoints, () -> arm.measured,
        () -> true, () -> arm.nowMicros));
    Pose wrong = Pose.of(new double[n + 1]);
    IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> controller.moveTo(wrong));
    assertEquals("the pose " + wrong.positions() + " has " + (n + 1) + " positions but the arm has " + n + " joint"
        + (n == 1 ? "" : "s") + ": " + arm.joints, e.getMessage());
    if (n > 1) assertThrows(IllegalArgumentException.class, () -> controller.moveTo(Pose.of(new double[n - 1])));
    MoveHandle right = controller.moveTo(Pose.of(new double[n]));
    controller.moveTo(Pose.named("STOW"));  // resolved by the daemon for its own joints
    ClientMemqTest.until(() -> goals.size() == 2);
    Thread.sleep(20);
    assertEquals(2, goals.size(), "only the right poses were sent");
    assertEquals(n, goals.get(0).num_joints);
    assertEquals(1, right.requestId(), "the refused pose used no request id");
    controller.client().close();
    arm.controller.client().close();
  }

  @Test
  void aGuardOrASourceOfOtherJointsOrAStateOfAnotherCountIsRefused() throws Exception {
    Chain arm = new Chain(2);
    CyberPlannerClient client = arm.controller.client();
    ArmController.Parts parts =
        new ArmController.Parts(client, (guard, now) -> {}, arm.armJoints, () -> arm.measured, () -> true, () -> 0L);
    IllegalArgumentException guard = assertThrows(IllegalArgumentException.class,
        () -> new ArmController(parts, new SetpointGuard(JointChain.of("shoulder")), new HoldFallback(arm.armJoints)));
    assertEquals("the guard's joints (0 shoulder) are not the arm's (0 shoulder, 1 elbow)", guard.getMessage());
    SetpointSource threeJoints = new SetpointSource() {
      @Override
      public void poll(SetpointGuard g, long now) {}

      @Override
      public void checkJoints(JointChain joints) {
        throw new IllegalArgumentException("not " + joints);
      }
    };
    assertThrows(IllegalArgumentException.class, () -> new ArmController(
        new ArmController.Parts(client, threeJoints, arm.armJoints, () -> arm.measured, () -> true, () -> 0L)));
    assertThrows(IllegalArgumentException.class, () -> new ArmController.Parts(client, threeJoints, List.of(),
        () -> arm.measured, () -> true, () -> 0L));
    assertThrows(IllegalArgumentException.class, () -> new ArmController.Parts(client, threeJoints,
        List.of(arm.armJoints.get(0), arm.armJoints.get(0)), () -> arm.measured, () -> true, () -> 0L));
    arm.measured = ArmState.of(0.1, 0.0);
    IllegalArgumentException state = assertThrows(IllegalArgumentException.class, arm.controller::periodic);
    assertEquals("the measured state has 1 joints, the arm 2: 0 shoulder, 1 elbow", state.getMessage());
    client.close();
  }

  @Test
  void theDaemonsJointNamesMustBeTheArmsOwn() throws Exception {
    LCM lcm = new LCM("memq://");
    ArmController controller = controller(lcm);
    controller.periodic();
    assertEquals(SetpointGuard.Verdict.USE, controller.verdict());
    arm_daemon_status_t other = ClientMemqTest.daemonStatus(arm_daemon_status_t.MODE_MOVING);
    other.joint_names = new String[] {"shoulder", "elbow"};
    lcm.publish("ARM_DAEMON_STATUS", other);
    ClientMemqTest.until(() -> !controller.client().daemonJointNames().isEmpty());
    int applied = joint0Requests.size();
    controller.periodic();
    assertEquals(SetpointGuard.Verdict.JOINTS_MISMATCH, controller.verdict());
    assertArrayEquals(new double[] {0.3, 0.0, 0.37}, joint0Requests.get(applied), "held, not the setpoint");
    lcm.publish("ARM_DAEMON_STATUS", ClientMemqTest.daemonStatus(arm_daemon_status_t.MODE_MOVING));
    ClientMemqTest.until(() -> controller.client().daemonJointNames().equals(List.of("elevator", "arm")));
    controller.periodic();
    assertEquals(SetpointGuard.Verdict.USE, controller.verdict());
    controller.client().close();
  }
}
