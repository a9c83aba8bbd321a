package cyberplanner.roborio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
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
    MoveHandle first = client.moveTo(Pose.of(1.22, 5.69).withCoral());
    MoveHandle second = client.moveTo(new Pose(0.58, 2.97, false, true, "open"));
    until(() -> goals.size() == 2);
    assertEquals(100, first.requestId());
    assertEquals(101, second.requestId());
    assertEquals(1.22, goals.get(0).elevator_m);
    assertTrue(goals.get(0).held_coral);
    assertEquals("open", goals.get(1).scene_name);
    assertTrue(goals.get(1).held_algae);
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
    MoveHandle failed = client.moveTo(Pose.of(1.98, 5.39).withCoral());
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
    arm_daemon_status_t status = new arm_daemon_status_t();
    status.mode = arm_daemon_status_t.MODE_MOVING;
    lcm.publish("ARM_DAEMON_STATUS", status);
    until(() -> client.daemonMode() == DaemonMode.MOVING);
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
    arm_daemon_status_t released = new arm_daemon_status_t();
    released.mode = 5;
    lcm.publish("ARM_DAEMON_STATUS", released);
    until(() -> client.daemonMode() == DaemonMode.RELEASED);
    assertFalse(DaemonMode.RELEASED.streams());
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
    client.publishState(0.2, 0.01, 1.57, -0.02, true, false);
    until(() -> states.size() == 1);
    arm_state_t s = states.get(0);
    assertEquals(0.2, s.elevator_m);
    assertEquals(0.01, s.elevator_mps);
    assertEquals(1.57, s.arm_rad);
    assertEquals(-0.02, s.arm_radps);
    assertTrue(s.held_coral);
    assertFalse(s.held_algae);
    assertTrue(Math.abs(s.utime - System.currentTimeMillis() * 1000) < 5_000_000);
    client.close();
  }
}
