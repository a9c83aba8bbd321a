package cyberplanner.roborio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import cyberplanner.arm_goal_t;
import cyberplanner.arm_state_t;
import java.net.SocketException;
import java.util.List;
import lcm.lcm.LCM;
import org.junit.jupiter.api.Test;

/**
 * The client without a multicast route (docs/roborio.md, "Start-up without a network"): it is
 * built, its state says why it is not connected, moves fail at once with that reason, and it
 * connects (and publishes) once LCM opens. The real missing route is the "noroute" test.
 */
class LcmLinkTest {
  @Test
  void theClientStartsWithoutARouteAndConnectsWhenOneAppears() throws Exception {
    LCM memq = new LCM("memq://");
    List<arm_state_t> states = ClientMemqTest.collect(memq, "ARM_STATE", arm_state_t::new);
    List<arm_goal_t> goals = ClientMemqTest.collect(memq, "ARM_GOAL", arm_goal_t::new);
    boolean[] route = {false};
    CyberPlannerClient client = new CyberPlannerClient(() -> {
      if (!route[0]) throw new SocketException("No such device");
      return memq;
    }, Channels.DEFAULT, 1);
    assertFalse(client.link().isConnected());
    assertEquals("SocketException: No such device", client.link().lastError());
    client.publishState(ArmState.of(0.2, 0, 1.57, 0));  // dropped, not thrown
    MoveHandle early = client.moveTo(Pose.of(0.2, 1.57));
    assertEquals(MoveState.FAILED, early.state());
    assertTrue(early.reason().contains("No such device"), early.reason());
    assertFalse(client.release());

    route[0] = true;
    Thread.sleep(Math.round(CyberPlannerClient.RETRY_S * 1000) + 50);
    client.publishState(ArmState.of(0.2, 0, 1.57, 0));
    assertTrue(client.link().isConnected());
    assertEquals("", client.link().lastError());
    MoveHandle later = client.moveTo(Pose.of(0.58, 2.97));
    ClientMemqTest.until(() -> states.size() == 1 && goals.size() == 1);
    assertEquals(later.requestId(), goals.get(0).request_id);
    client.close();
  }

  @Test
  void failedAttemptsAreSpacedByTheRetryInterval() {
    long[] nowNanos = {0};
    int[] attempts = {0};
    LcmLink link = new LcmLink(() -> {
      attempts[0]++;
      throw new SocketException("Network is unreachable");
    }, 1.0, () -> nowNanos[0], lcm -> {});
    for (int loop = 0; loop < 150; ++loop, nowNanos[0] += 20_000_000L) link.get();  // 3 s of a 50 Hz loop
    assertEquals(3, attempts[0]);
    assertEquals(3, link.failedAttempts());
  }
}
