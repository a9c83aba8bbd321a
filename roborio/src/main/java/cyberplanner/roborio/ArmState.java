package cyberplanner.roborio;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * The measured state the robot publishes on ARM_STATE: each joint's position and velocity (m and
 * m/s for a prismatic joint, rad and rad/s for a revolute one; joints by index in the order of the
 * config's [[joints]], 1 to JointChain.MAX_JOINTS of them) and the game pieces held now, by their
 * config names. Positions are not checked for being finite: a bad encoder reading must not throw
 * in the robot loop; the daemon ignores such a state (counting it in decode_errors), stops when its
 * state goes stale, and the guard falls back. The shape is checked (as many velocities as
 * positions, 1 to MAX_JOINTS, no null) and so are the pieces, as in Pose (IllegalArgumentException).
 */
public record ArmState(List<Double> positions, List<Double> velocities, List<String> pieces) {
  public ArmState {
    if (positions == null || velocities == null) throw new IllegalArgumentException("positions or velocities is null");
    if (positions.size() != velocities.size()) {
      throw new IllegalArgumentException(positions.size() + " positions " + positions + " but " + velocities.size()
          + " velocities " + velocities);
    }
    if (positions.isEmpty() || positions.size() > Checks.MAX_JOINTS) {
      throw new IllegalArgumentException(positions.size() + " joints measured: a robot has 1 to " + Checks.MAX_JOINTS);
    }
    for (int i = 0; i < positions.size(); ++i) {
      if (positions.get(i) == null || velocities.get(i) == null) {
        throw new IllegalArgumentException("joint " + i + "'s measured position or velocity is null");
      }
    }
    positions = List.copyOf(positions);
    velocities = List.copyOf(velocities);
    pieces = Checks.pieces(pieces);
  }

  /**
   * Each joint measured, nothing held: its position and its velocity, joint by joint in chain order
   * ({@code ArmState.of(elevatorM, elevatorMps, armRad, armRadps)} for two joints).
   */
  public static ArmState of(double... positionVelocityPairs) {
    if (positionVelocityPairs == null || positionVelocityPairs.length % 2 != 0) {
      throw new IllegalArgumentException("a state is a position and a velocity per joint, not "
          + Arrays.toString(positionVelocityPairs));
    }
    List<Double> positions = new ArrayList<>();
    List<Double> velocities = new ArrayList<>();
    for (int i = 0; i < positionVelocityPairs.length; i += 2) {
      positions.add(positionVelocityPairs[i]);
      velocities.add(positionVelocityPairs[i + 1]);
    }
    return new ArmState(positions, velocities, List.of());
  }

  /** Each joint measured, nothing held: positions[i] and velocities[i] of joint i. */
  public static ArmState of(double[] positions, double[] velocities) {
    if (positions == null || velocities == null) throw new IllegalArgumentException("positions or velocities is null");
    return new ArmState(Arrays.stream(positions).boxed().toList(), Arrays.stream(velocities).boxed().toList(),
        List.of());
  }

  /** The same state holding these pieces (replacing any named before; none: nothing held). */
  public ArmState holding(String... pieces) {
    if (pieces == null) throw new IllegalArgumentException("pieces is null");
    return holding(Arrays.asList(pieces));
  }

  public ArmState holding(List<String> pieces) {
    return new ArmState(positions, velocities, pieces);
  }

  /** How many joints are measured. */
  public int count() {
    return positions.size();
  }

  /** Joint index's position, m or rad. */
  public double position(int index) {
    return positions.get(index);
  }

  /** Joint index's velocity, m/s or rad/s. */
  public double velocity(int index) {
    return velocities.get(index);
  }
}
