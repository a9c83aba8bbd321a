package cyberplanner.roborio;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;

import cyberplanner.roborio.SetpointGuard.Verdict;
import cyberplanner.roborio.can.CanFrame;
import cyberplanner.roborio.can.DaemonMode;
import cyberplanner.roborio.can.DaemonStatus;
import cyberplanner.roborio.can.Setpoint;
import cyberplanner.roborio.can.SetpointFrame;
import cyberplanner.roborio.can.StatusFrame;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * One setpoint stream per joint on the CAN bus, each on the device the daemon's [daemon.devices]
 * gives the joint by name, or on the daemon's default numbering (docs/can-protocol.md).
 */
class CanFrameRouterTest {
  static final List<String> NAMES = List.of("shoulder", "elbow", "wrist");

  static void offer(CanFrameRouter router, SetpointGuard guard, CanFrame frame) {
    router.offer(guard, frame.id(), frame.data(), frame.length(), 0);
  }

  static void setpoint(CanFrameRouter router, SetpointGuard guard, int device, double position) {
    offer(router, guard, SetpointFrame.encode(new Setpoint(device, position, 0.0, 0.0, 0)).value());
  }

  static void status(CanFrameRouter router, SetpointGuard guard, int device) {
    offer(router, guard, StatusFrame.encode(new DaemonStatus(device, DaemonMode.MOVING, 0, 0, 0, 0)).value());
  }

  @ParameterizedTest
  @ValueSource(ints = {1, 2, 3})
  void theDefaultDevicesAreOneToNAndTheStatusNPlusOne(int n) {
    JointChain joints = JointChain.of(NAMES.subList(0, n));
    SetpointGuard guard = new SetpointGuard(joints);
    CanFrameRouter router = CanFrameRouter.defaults();
    router.checkJoints(joints);
    status(router, guard, n + 1);
    for (int i = 0; i < n; ++i) setpoint(router, guard, i + 1, 0.1 * (i + 1));
    setpoint(router, guard, n + 2, 9.0);  // no joint's: foreign
    for (int i = 0; i < n; ++i) assertEquals(0.1 * (i + 1), guard.latest(i).position(), 1e-9, "joint " + i);
    assertEquals(Verdict.USE, guard.verdict(0));
    assertEquals(1, router.foreignFrames());
    assertEquals(n + 1, router.statusDevice(joints));
  }

  @ParameterizedTest
  @ValueSource(ints = {1, 2, 3})
  void theConfigsDevicesGoToTheJointsTheyName(int n) {
    JointChain joints = JointChain.of(NAMES.subList(0, n));
    // Devices in another order than the joints': the names decide, not the numbers.
    Map<String, Integer> devices = new java.util.HashMap<>(Map.of("status", 40));
    for (int i = 0; i < n; ++i) devices.put(NAMES.get(i), 30 - i);
    CanFrameRouter router = CanFrameRouter.of(devices);
    SetpointGuard guard = new SetpointGuard(joints);
    status(router, guard, 40);
    for (int i = n - 1; i >= 0; --i) setpoint(router, guard, 30 - i, i + 0.5);
    for (int i = 0; i < n; ++i) assertEquals(i + 0.5, guard.latest(NAMES.get(i)).position(), 1e-9);
    assertEquals(Verdict.USE, guard.verdict(0));
    int[] expected = new int[n];
    for (int i = 0; i < n; ++i) expected[i] = 30 - i;
    assertArrayEquals(expected, router.jointDevices(joints));
    status(router, guard, n + 1);  // the default status device is not this config's
    assertEquals(1, router.foreignFrames());
  }

  @Test
  void aTableThatDoesNotNameEveryJointOrNamesAnotherIsRefusedNamingTheJoints() {
    JointChain three = JointChain.of(NAMES);
    CanFrameRouter two = CanFrameRouter.of(Map.of("shoulder", 1, "elbow", 2, "status", 3));
    IllegalArgumentException missing = assertThrows(IllegalArgumentException.class, () -> two.checkJoints(three));
    assertEquals("the devices {elbow=2, shoulder=1, status=3} have no key for joint wrist (the joints: 0 shoulder, "
        + "1 elbow, 2 wrist)", missing.getMessage());
    IllegalArgumentException extra =
        assertThrows(IllegalArgumentException.class, () -> two.checkJoints(JointChain.of("shoulder")));
    assertEquals("device key \"elbow\" is neither a joint's name (0 shoulder) nor \"status\"", extra.getMessage());
    // A guard of other joints than the table's: refused at the first frame, not misrouted.
    SetpointGuard guard = new SetpointGuard(three);
    assertThrows(IllegalArgumentException.class, () -> setpoint(two, guard, 1, 0.0));
    assertNull(guard.latest(0));
    assertThrows(IllegalArgumentException.class, () -> CanFrameRouter.of(Map.of("shoulder", 1)));  // no status
    assertThrows(IllegalArgumentException.class, () -> CanFrameRouter.of(Map.of("shoulder", 1, "status", 1)));
    assertThrows(IllegalArgumentException.class, () -> CanFrameRouter.of(Map.of("shoulder", 63, "status", 1)));
    assertThrows(IllegalArgumentException.class, () -> CanFrameRouter.of(Map.of("shoulder", -1, "status", 1)));
  }
}
