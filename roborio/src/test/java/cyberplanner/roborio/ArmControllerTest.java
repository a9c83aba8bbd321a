package cyberplanner.roborio;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
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
    guard.onSetpoint(Joint.JOINT_0, new Setpoint(1, 0.5, 0.1, 0.4, sequence & 0xFF), now);
    guard.onSetpoint(Joint.JOINT_1, new Setpoint(2, 1.0, 0.0, 0.1, sequence & 0xFF), now);
    sequence += 2;  // every other frame lost
  };

  ArmController controller(LCM lcm) {
    CyberPlannerClient client = new CyberPlannerClient(lcm, Channels.DEFAULT, 9);
    return new ArmController(new ArmController.Parts(client, source, joint0, joint1,
        () -> measured, () -> enabled, () -> nowMicros),
        JointGravity.constant(0.37), JointGravity.cosine(0.21));
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
    assertEquals(2, inputs.joint0LostFrames);  // one per loop after the first
    assertEquals(2, inputs.joint1LostFrames);
    assertEquals(0, inputs.joint0RepeatedFrames);
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
}
