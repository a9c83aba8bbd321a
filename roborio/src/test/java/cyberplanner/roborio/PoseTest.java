package cyberplanner.roborio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** Pose, ArmState and JointChain: immutable values by joint index and name, pieces by name, checked when built. */
class PoseTest {
  @Test
  void eachWithMethodReturnsANewPoseAndLeavesTheOldOne() {
    Pose base = Pose.of(1.22, 5.69);
    Pose scoring = base.holding("cone", "cube").inScene("grid").atSceneOffset(0.25);
    assertNotSame(base, scoring);
    assertEquals(new Pose(List.of(1.22, 5.69), "", List.of(), "", 0.0), base);
    assertEquals(new Pose(List.of(1.22, 5.69), "", List.of("cone", "cube"), "grid", 0.25), scoring);
    assertEquals(List.of("cube"), scoring.holding("cube").pieces(), "holding replaces the pieces named before");
    assertEquals(List.of(), scoring.holding().pieces());
    assertEquals(1.22, scoring.position(0));
    assertEquals(5.69, scoring.position(1));
    assertThrows(IllegalArgumentException.class, () -> scoring.position(2));
  }

  @Test
  void thePiecesCannotBeChangedFromOutside() {
    List<String> mine = new ArrayList<>(List.of("cone"));
    Pose pose = Pose.of(0.2, 1.0).holding(mine);
    mine.add("cube");
    assertEquals(List.of("cone"), pose.pieces());
    assertThrows(UnsupportedOperationException.class, () -> pose.pieces().add("cube"));
    String[] array = {"cone"};
    Pose fromArray = Pose.of(0.2, 1.0).holding(array);
    array[0] = "cube";
    assertEquals(List.of("cone"), fromArray.pieces());
  }

  @Test
  void theCanonicalConstructorChecksAsTheWithMethodsDo() {
    List<Double> two = List.of(0.2, 1.0);
    assertThrows(IllegalArgumentException.class, () -> new Pose(two, "", null, "", 0));
    assertThrows(IllegalArgumentException.class, () -> new Pose(two, "", List.of(), null, 0));
    assertThrows(IllegalArgumentException.class, () -> new Pose(two, "", List.of("a", "b", "c", "d", "e"), "", 0));
    assertThrows(IllegalArgumentException.class,
        () -> new Pose(List.of(Double.NEGATIVE_INFINITY, 1.0), "", List.of(), "", 0));
    assertThrows(IllegalArgumentException.class, () -> Pose.of(0.2, 1.0).inScene("r\u00e9cif"));
    assertThrows(IllegalArgumentException.class, () -> Pose.of(0.2, 1.0).holding("line\nbreak"));
    assertEquals(4, Pose.MAX_PIECES);
  }

  @Test
  void anArmStateCarriesEachJointByIndexAndItsPieces() {
    ArmState state = ArmState.of(0.3, 0.1, 1.5, -0.2).holding("coral");
    assertEquals(2, state.count());
    assertEquals(0.3, state.position(0));
    assertEquals(0.1, state.velocity(0));
    assertEquals(1.5, state.position(1));
    assertEquals(-0.2, state.velocity(1));
    assertEquals(List.of("coral"), state.pieces());
    assertEquals(List.of(), ArmState.of(0, 0, 0, 0).pieces());
    assertThrows(IllegalArgumentException.class, () -> state.holding("a", "b", "c", "d", "e"));
    assertThrows(IllegalArgumentException.class, () -> state.holding((String) null));
    // A bad reading must not throw in the robot loop: the daemon refuses it and stops.
    assertEquals(Double.NaN, ArmState.of(Double.NaN, 0, 0, 0).position(0));
  }

  @Test
  void anArmStateHasOneToFourJointsEachWithAVelocity() {
    ArmState one = ArmState.of(0.4, 0.01);
    assertEquals(1, one.count());
    ArmState three = ArmState.of(new double[] {0.1, 0.2, 0.3}, new double[] {-1, -2, -3});
    assertEquals(3, three.count());
    assertEquals(0.3, three.position(2));
    assertEquals(-3, three.velocity(2));
    assertEquals(three, ArmState.of(0.1, -1, 0.2, -2, 0.3, -3));
    IllegalArgumentException odd = assertThrows(IllegalArgumentException.class, () -> ArmState.of(0.1, 0.2, 0.3));
    assertEquals("a state is a position and a velocity per joint, not [0.1, 0.2, 0.3]", odd.getMessage());
    assertThrows(IllegalArgumentException.class, () -> ArmState.of());
    assertThrows(IllegalArgumentException.class, () -> ArmState.of(1, 0, 2, 0, 3, 0, 4, 0, 5, 0));
    assertThrows(IllegalArgumentException.class, () -> ArmState.of(new double[] {1, 2}, new double[] {0}));
  }

  @Test
  void jointsAreAddressedByIndexAndByTheirNames() {
    JointChain chain = JointChain.of("shoulder", "elbow", "wrist");
    assertEquals(3, chain.count());
    assertEquals("elbow", chain.name(1));
    assertEquals(2, chain.index("wrist"));
    assertEquals(List.of("shoulder", "elbow", "wrist"), chain.names());
    assertEquals("0 shoulder, 1 elbow, 2 wrist", chain.toString());
    IllegalArgumentException unknown = assertThrows(IllegalArgumentException.class, () -> chain.index("arm"));
    assertEquals("no joint \"arm\": the joints are 0 shoulder, 1 elbow, 2 wrist", unknown.getMessage());
    assertThrows(IllegalArgumentException.class, () -> chain.name(3));
    assertThrows(IllegalArgumentException.class, () -> chain.checkIndex(-1));
    assertEquals(JointChain.of("shoulder", "elbow", "wrist"), chain);
    // A pose by the joints' names goes in chain order.
    assertEquals(Pose.of(0.4, 1.2, -0.6), chain.pose(Map.of("wrist", -0.6, "shoulder", 0.4, "elbow", 1.2)));
    assertThrows(IllegalArgumentException.class, () -> chain.pose(Map.of("shoulder", 0.4, "elbow", 1.2)));
    assertThrows(IllegalArgumentException.class,
        () -> chain.pose(Map.of("shoulder", 0.4, "elbow", 1.2, "wrist", 0.0, "arm", 1.0)));
    // 1 to 4 joints, named, each name once.
    assertEquals(1, JointChain.of("pivot").count());
    assertEquals(4, JointChain.MAX_JOINTS);
    assertThrows(IllegalArgumentException.class, () -> JointChain.of());
    assertThrows(IllegalArgumentException.class, () -> JointChain.of("a", "b", "c", "d", "e"));
    assertThrows(IllegalArgumentException.class, () -> JointChain.of("arm", "arm"));
    assertThrows(IllegalArgumentException.class, () -> JointChain.of("arm", ""));
    assertThrows(IllegalArgumentException.class, () -> JointChain.of("arm", null));
    assertThrows(IllegalArgumentException.class, () -> JointChain.of("\u00e9paule"));
  }

  @Test
  void aPoseOfAnotherLengthThanTheChainIsRefusedSayingBoth() {
    JointChain three = JointChain.of("shoulder", "elbow", "wrist");
    IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> three.check(Pose.of(0.2, 1.0)));
    assertEquals("the pose [0.2, 1.0] has 2 positions but the arm has 3 joints: 0 shoulder, 1 elbow, 2 wrist",
        e.getMessage());
    e = assertThrows(IllegalArgumentException.class, () -> JointChain.of("pivot").check(Pose.of(0.2, 1.0)));
    assertEquals("the pose [0.2, 1.0] has 2 positions but the arm has 1 joint: 0 pivot", e.getMessage());
    Pose named = Pose.named("STOW");
    assertEquals(named, three.check(named));  // the daemon resolves a name with its own joints
    assertEquals(Pose.of(0.1, 0.2, 0.3), three.check(Pose.of(0.1, 0.2, 0.3)));
  }
}
