package cyberplanner.roborio;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import cyberplanner.arm_cancel_t;
import cyberplanner.arm_daemon_status_t;
import cyberplanner.arm_goal_t;
import cyberplanner.arm_plan_status_t;
import cyberplanner.arm_state_t;
import cyberplanner.roborio.can.DaemonMode;
import java.io.IOException;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import lcm.lcm.LCM;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;

/** The client against a scripted daemon on LCM's in-process transport (memq://). */
class ClientMemqTest {
  static void status(LCM lcm, long requestId, byte status, String reason) {
    arm_plan_status_t m = new arm_plan_status_t();
    m.request_id = requestId;
    m.status = status;
    m.reason = reason;
    m.duration_s = status == arm_plan_status_t.STATUS_EXECUTING ? 0.5 : 0.0;
    lcm.publish("ARM_PLAN_STATUS", m);
  }

  /** A daemon status of the reference robot's config (joint 0 an elevator, joint 1 an arm). */
  static arm_daemon_status_t daemonStatus(byte mode) {
    arm_daemon_status_t m = new arm_daemon_status_t();
    m.mode = mode;
    m.num_joints = 2;
    m.joint_names = new String[] {"elevator", "arm"};
    m.joint_units = new String[] {"m", "rad"};
    return m;
  }

  interface Decoder<T> {
    T decode(lcm.lcm.LCMDataInputStream in) throws IOException;
  }

  /** Every message on channel, decoded (LCM's thread appends). */
  static <T> List<T> collect(LCM lcm, String channel, Decoder<T> decoder) {
    List<T> out = new CopyOnWriteArrayList<>();
    lcm.subscribe(channel, (l, c, in) -> {
      try {
        out.add(decoder.decode(in));
      } catch (IOException e) {
        throw new AssertionError(e);
      }
    });
    return out;
  }

  static void until(java.util.function.BooleanSupplier condition) throws InterruptedException {
    for (int i = 0; i < 400 && !condition.getAsBoolean(); ++i) Thread.sleep(5);
    assertTrue(condition.getAsBoolean(), "timed out");
  }

  @Test
  void movesGetRequestIdsAndFollowTheirStatusToTheEnd() throws Exception {
    LCM lcm = new LCM("memq://");
    List<arm_goal_t> goals = collect(lcm, "ARM_GOAL", arm_goal_t::new);
    CyberPlannerClient client = new CyberPlannerClient(lcm, Channels.DEFAULT, 100);
    MoveHandle first = client.moveTo(Pose.of(1.22, 5.69).holding("coral"));
    MoveHandle second =
        client.moveTo(Pose.of(0.58, 2.97).holding("algae", "coral").inScene("reef").atSceneOffset(0.12));
    until(() -> goals.size() == 2);
    assertEquals(100, first.requestId());
    assertEquals(101, second.requestId());
    arm_goal_t plain = goals.get(0);
    assertEquals(2, plain.num_joints);  // from the Pose's length
    assertEquals("", plain.pose_name);
    assertArrayEquals(new double[] {1.22, 5.69}, plain.position);
    assertEquals(1, plain.num_pieces);
    assertArrayEquals(new String[] {"coral"}, plain.pieces);
    assertEquals("", plain.scene_name);  // the default scene, where the config puts it
    assertEquals(0.0, plain.scene_offset_m);
    arm_goal_t placed = goals.get(1);
    assertArrayEquals(new double[] {0.58, 2.97}, placed.position);
    assertEquals(2, placed.num_pieces);
    assertArrayEquals(new String[] {"algae", "coral"}, placed.pieces);
    assertEquals("reef", placed.scene_name);
    assertEquals(0.12, placed.scene_offset_m);
    assertEquals(MoveState.SENT, first.state());

    status(lcm, 100, arm_plan_status_t.STATUS_ACCEPTED, "");
    until(() -> first.state() == MoveState.ACCEPTED);
    status(lcm, 100, arm_plan_status_t.STATUS_CANCELLED, "superseded by request 101");
    status(lcm, 101, arm_plan_status_t.STATUS_PLANNING, "");
    status(lcm, 101, arm_plan_status_t.STATUS_EXECUTING, "");
    until(() -> second.state() == MoveState.EXECUTING);
    assertEquals(0.5, second.durationS());
    assertEquals(MoveState.CANCELLED, first.await(2));
    assertEquals("superseded by request 101", first.reason());
    status(lcm, 101, arm_plan_status_t.STATUS_DONE, "");
    assertEquals(MoveState.DONE, second.await(2));
    // Finished is final: a late message changes nothing.
    status(lcm, 101, arm_plan_status_t.STATUS_FAILED, "late");
    Thread.sleep(20);
    assertEquals(MoveState.DONE, second.state());
    client.close();
  }

  @Test
  void unansweredMovesAreForgottenAfterAThousandNewerOnes() throws Exception {
    LCM lcm = new LCM("memq://");
    CyberPlannerClient client = new CyberPlannerClient(lcm, Channels.DEFAULT, 1);
    MoveHandle forgotten = client.moveTo(Pose.of(0.2, 1.57));
    MoveHandle kept = client.moveTo(Pose.of(0.2, 1.57));
    for (int i = 0; i < 999; ++i) client.moveTo(Pose.of(0.2, 1.57));  // ids 3..1001
    status(lcm, forgotten.requestId(), arm_plan_status_t.STATUS_DONE, "");
    status(lcm, kept.requestId(), arm_plan_status_t.STATUS_DONE, "");
    assertEquals(MoveState.DONE, kept.await(2));
    assertEquals(MoveState.SENT, forgotten.state());
    client.close();
  }

  @Test
  void rejectedAndFailedCarryTheirReason() throws Exception {
    LCM lcm = new LCM("memq://");
    CyberPlannerClient client = new CyberPlannerClient(lcm, Channels.DEFAULT, 7);
    MoveHandle rejected = client.moveTo(Pose.of(5.0, 1.0));
    MoveHandle failed = client.moveTo(Pose.of(1.98, 5.39).holding("coral"));
    status(lcm, 7, arm_plan_status_t.STATUS_REJECTED, "goal out of range");
    status(lcm, 8, arm_plan_status_t.STATUS_FAILED, "no path");
    assertEquals(MoveState.REJECTED, rejected.await(2));
    assertEquals("goal out of range", rejected.reason());
    assertEquals(MoveState.FAILED, failed.await(2));
    assertEquals("request 8 failed: no path", failed.toString());
    client.close();
  }

  @Test
  void liveness_isTheAgeOfTheDaemonStatusAndModeComesWithIt() throws Exception {
    LCM lcm = new LCM("memq://");
    CyberPlannerClient client = new CyberPlannerClient(lcm, Channels.DEFAULT, 1);
    assertNull(client.daemonMode());
    assertFalse(client.isDaemonAlive(10));
    assertEquals(Double.POSITIVE_INFINITY, client.daemonStatusAgeS());
    assertEquals("", client.daemonJoints());
    assertEquals(List.of(), client.daemonJointNames());
    lcm.publish("ARM_DAEMON_STATUS", daemonStatus(arm_daemon_status_t.MODE_MOVING));
    until(() -> client.daemonMode() == DaemonMode.MOVING);
    assertEquals("elevator m, arm rad", client.daemonJoints());
    assertEquals(List.of("elevator", "arm"), client.daemonJointNames());
    assertTrue(client.isDaemonAlive(1.0));
    Thread.sleep(60);
    assertTrue(client.daemonStatusAgeS() >= 0.05);
    assertFalse(client.isDaemonAlive(0.05));
    // A message of another type on the channel is counted, not thrown.
    lcm.publish("ARM_DAEMON_STATUS", new arm_state_t());
    until(() -> client.undecodableMessages() == 1);
    client.close();
  }

  @Test
  void cancelHoldsAMoveAndReleaseStopsWhateverIsActive() throws Exception {
    LCM lcm = new LCM("memq://");
    List<arm_cancel_t> cancels = collect(lcm, "ARM_CANCEL", arm_cancel_t::new);
    CyberPlannerClient client = new CyberPlannerClient(lcm, Channels.DEFAULT, 40);
    MoveHandle move = client.moveTo(Pose.of(1.22, 5.69));
    assertTrue(client.cancel(move, CancelAction.HOLD));
    assertTrue(client.release());
    until(() -> cancels.size() == 2);
    assertEquals(40, cancels.get(0).request_id);
    assertEquals(arm_cancel_t.ACTION_HOLD, cancels.get(0).action);
    assertEquals(-1, cancels.get(1).request_id);
    assertEquals(arm_cancel_t.ACTION_RELEASE, cancels.get(1).action);
    status(lcm, 40, arm_plan_status_t.STATUS_CANCELLED, "cancelled by the robot");
    assertEquals(MoveState.CANCELLED, move.await(2));
    // The daemon's new mode 5 (manual override) decodes.
    lcm.publish("ARM_DAEMON_STATUS", daemonStatus((byte) 5));
    until(() -> client.daemonMode() == DaemonMode.RELEASED);
    assertFalse(DaemonMode.RELEASED.streams());
    client.close();
  }

  /**
   * A named pose goes as its name with no positions, for the daemon to resolve with its config
   * (docs/lcm.md, "Named goals"); a pose of N values sends N.
   */
  @Test
  void aNamedPoseSendsItsNameAndAnyPoseItsOwnJointCount() throws Exception {
    LCM lcm = new LCM("memq://");
    List<arm_goal_t> goals = collect(lcm, "ARM_GOAL", arm_goal_t::new);
    CyberPlannerClient client = new CyberPlannerClient(lcm, Channels.DEFAULT, 1);
    client.moveTo(Pose.named("L3").holding("coral"));
    client.moveTo(Pose.of(0.1, 0.2, 0.3));
    until(() -> goals.size() == 2);
    arm_goal_t named = goals.get(0);
    assertEquals("L3", named.pose_name);
    assertEquals(0, named.num_joints);
    assertEquals(0, named.position.length);
    assertArrayEquals(new String[] {"coral"}, named.pieces);
    arm_goal_t three = goals.get(1);
    assertEquals("", three.pose_name);
    assertEquals(3, three.num_joints);
    assertArrayEquals(new double[] {0.1, 0.2, 0.3}, three.position);
    Pose pose = Pose.named("STOW").inScene("reef");
    assertTrue(pose.isNamed());
    assertEquals(List.of(), pose.positions());
    assertThrows(IllegalStateException.class, () -> pose.position(0));
    assertEquals(Pose.of(1.22, 5.69), new Pose(List.of(1.22, 5.69), "", List.of(), "", 0.0));
    assertEquals(5.69, Pose.of(1.22, 5.69).position(1));
    assertThrows(IllegalArgumentException.class, () -> Pose.named(""));
    assertThrows(IllegalArgumentException.class, () -> Pose.named(null));
    assertThrows(IllegalArgumentException.class, () -> Pose.named("L\n3"));
    assertThrows(IllegalArgumentException.class, () -> Pose.of(1, 2, 3, 4, 5));
    assertThrows(IllegalArgumentException.class, () -> Pose.of());
    assertThrows(IllegalArgumentException.class, () -> new Pose(List.of(1.0), "L3", List.of(), "", 0.0));
    client.close();
  }

  @Test
  void theRobotLanUrlUsesTheTeamUsePort5810() {
    assertEquals("udpm://239.255.76.67:5810?ttl=1", CyberPlannerClient.ROBOT_LAN_URL);
  }

  @Test
  void publishesTheMeasuredState() throws Exception {
    LCM lcm = new LCM("memq://");
    List<arm_state_t> states = collect(lcm, "ARM_STATE", arm_state_t::new);
    CyberPlannerClient client = new CyberPlannerClient(lcm, Channels.DEFAULT, 1);
    client.publishState(ArmState.of(0.2, 0.01, 1.57, -0.02).holding("coral"));
    client.publishState(ArmState.of(0.3, 0.0, 1.6, 0.0));
    until(() -> states.size() == 2);
    arm_state_t s = states.get(0);
    assertEquals(2, s.num_joints);
    assertArrayEquals(new double[] {0.2, 1.57}, s.position);
    assertArrayEquals(new double[] {0.01, -0.02}, s.velocity);
    assertEquals(1, s.num_pieces);
    assertArrayEquals(new String[] {"coral"}, s.pieces);
    assertTrue(Math.abs(s.utime - System.currentTimeMillis() * 1000) < 5_000_000);
    assertEquals(0, states.get(1).num_pieces);
    // Any chain: num_joints is the state's own count.
    client.publishState(ArmState.of(0.7, 0.1));
    client.publishState(ArmState.of(0.1, 1, 0.2, 2, 0.3, 3));
    until(() -> states.size() == 4);
    assertEquals(1, states.get(2).num_joints);
    assertArrayEquals(new double[] {0.7}, states.get(2).position);
    assertEquals(3, states.get(3).num_joints);
    assertArrayEquals(new double[] {0.1, 0.2, 0.3}, states.get(3).position);
    assertArrayEquals(new double[] {1, 2, 3}, states.get(3).velocity);
    assertThrows(IllegalArgumentException.class, () -> client.publishState(null));
    client.close();
  }

  @Test
  void aBadGoalThrowsAtTheCallAndSendsNothing() throws Exception {
    LCM lcm = new LCM("memq://");
    List<arm_goal_t> goals = collect(lcm, "ARM_GOAL", arm_goal_t::new);
    CyberPlannerClient client = new CyberPlannerClient(lcm, Channels.DEFAULT, 1);
    List<Executable> mistakes = List.of(
        () -> client.moveTo(null),
        () -> client.moveTo(Pose.of(Double.NaN, 1.0)),
        () -> client.moveTo(Pose.of(0.2, Double.POSITIVE_INFINITY)),
        () -> client.moveTo(Pose.of(0.2, 1.0).holding("a", "b", "c", "d", "e")),
        () -> client.moveTo(Pose.of(0.2, 1.0).holding("coral", null)),
        () -> client.moveTo(Pose.of(0.2, 1.0).holding("")),
        () -> client.moveTo(Pose.of(0.2, 1.0).holding("cône")),  // LCM's Java encoder would mangle it
        () -> client.moveTo(Pose.of(0.2, 1.0).holding((String[]) null)),
        () -> client.moveTo(Pose.of(0.2, 1.0).inScene(null)),
        () -> client.moveTo(Pose.of(0.2, 1.0).atSceneOffset(Double.NaN)));
    for (Executable mistake : mistakes) assertThrows(IllegalArgumentException.class, mistake);
    client.moveTo(Pose.of(0.2, 1.0).holding("a", "b", "c", "d"));  // MAX_PIECES is allowed
    until(() -> goals.size() == 1);
    Thread.sleep(20);
    assertEquals(1, goals.size(), "only the valid goal was published");
    assertEquals(Pose.MAX_PIECES, goals.get(0).num_pieces);
    assertEquals(1, goals.get(0).request_id, "the mistakes used no request id");
    client.close();
  }
}
