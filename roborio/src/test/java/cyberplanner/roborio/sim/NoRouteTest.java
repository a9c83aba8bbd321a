package cyberplanner.roborio.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import cyberplanner.roborio.ArmState;
import cyberplanner.roborio.CyberPlannerClient;
import cyberplanner.roborio.MoveState;
import cyberplanner.roborio.Pose;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The client on a host with no multicast route, for real: tests/integration/roborio_integration_test.sh
 * runs this in a network namespace with only lo up and no route, where `new LCM(url)` throws
 * "No such device"; the test then adds the route itself (it runs as root inside that namespace)
 * and the client connects (docs/roborio.md, "Start-up without a network").
 */
@Tag("noroute")
class NoRouteTest {
  @Test
  void theClientStartsWithoutARouteAndConnectsWhenOneIsAdded() throws Exception {
    String url = System.getProperty("cyber.lcm.url", CyberPlannerClient.ROBOT_LAN_URL);
    try (CyberPlannerClient client = new CyberPlannerClient(url)) {
      assertFalse(client.link().isConnected());
      assertTrue(client.link().lastError().contains("No such device"), client.link().lastError());
      assertEquals(MoveState.FAILED, client.moveTo(Pose.of(0.2, 1.57)).state());
      Process route = new ProcessBuilder("ip", "route", "add", "224.0.0.0/4", "dev", "lo").inheritIO().start();
      assertEquals(0, route.waitFor());
      for (int i = 0; i < 300 && !client.link().isConnected(); ++i) {
        client.publishState(ArmState.of(0.2, 0, 1.57, 0));  // the robot loop, 100 Hz
        Thread.sleep(10);
      }
      assertTrue(client.link().isConnected(), client.link().lastError());
      assertEquals(MoveState.SENT, client.moveTo(Pose.of(0.2, 1.57)).state());
    }
  }
}
