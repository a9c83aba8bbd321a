package cyberplanner.roborio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Pose, ArmState and Joint: immutable values by joint index, pieces by name, checked when built. */
class PoseTest {
  @Test
  void eachWithMethodReturnsANewPoseAndLeavesTheOldOne() {
    Pose base = Pose.of(1.22, 5.69);
    Pose scoring = base.holding("cone", "cube").inScene("grid").atSceneOffset(0.25);
    assertNotSame(base, scoring);
    assertEquals(new Pose(1.22, 5.69, List.of(), "", 0.0), base);
    assertEquals(new Pose(1.22, 5.69, List.of("cone", "cube"), "grid", 0.25), scoring);
    assertEquals(List.of("cube"), scoring.holding("cube").pieces(), "holding replaces the pieces named before");
    assertEquals(List.of(), scoring.holding().pieces());
    assertEquals(1.22, scoring.position(Joint.JOINT_0));
    assertEquals(5.69, scoring.position(Joint.JOINT_1));
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
    assertThrows(IllegalArgumentException.class, () -> new Pose(0.2, 1.0, null, "", 0));
    assertThrows(IllegalArgumentException.class, () -> new Pose(0.2, 1.0, List.of(), null, 0));
    assertThrows(IllegalArgumentException.class, () -> new Pose(0.2, 1.0, List.of("a", "b", "c", "d", "e"), "", 0));
    assertThrows(IllegalArgumentException.class, () -> new Pose(Double.NEGATIVE_INFINITY, 1.0, List.of(), "", 0));
    assertThrows(IllegalArgumentException.class, () -> Pose.of(0.2, 1.0).inScene("r\u00e9cif"));
    assertThrows(IllegalArgumentException.class, () -> Pose.of(0.2, 1.0).holding("line\nbreak"));
    assertEquals(4, Pose.MAX_PIECES);
  }

  @Test
  void anArmStateCarriesEachJointByIndexAndItsPieces() {
    ArmState state = ArmState.of(0.3, 0.1, 1.5, -0.2).holding("coral");
    assertEquals(0.3, state.position(Joint.JOINT_0));
    assertEquals(0.1, state.velocity(Joint.JOINT_0));
    assertEquals(1.5, state.position(Joint.JOINT_1));
    assertEquals(-0.2, state.velocity(Joint.JOINT_1));
    assertEquals(List.of("coral"), state.pieces());
    assertEquals(List.of(), ArmState.of(0, 0, 0, 0).pieces());
    assertThrows(IllegalArgumentException.class, () -> state.holding("a", "b", "c", "d", "e"));
    assertThrows(IllegalArgumentException.class, () -> state.holding((String) null));
    // A bad reading must not throw in the robot loop: the daemon refuses it and stops.
    assertEquals(Double.NaN, ArmState.of(Double.NaN, 0, 0, 0).position(Joint.JOINT_0));
  }

  @Test
  void jointsAreIndexZeroAndOne() {
    assertEquals(2, Joint.COUNT);
    assertEquals(0, Joint.JOINT_0.index());
    assertEquals(1, Joint.JOINT_1.index());
    assertEquals(Joint.JOINT_1, Joint.of(1));
    assertThrows(IllegalArgumentException.class, () -> Joint.of(2));
    assertThrows(IllegalArgumentException.class, () -> Joint.of(-1));
  }
}
