package cyberplanner.roborio.sim;

import cyberplanner.roborio.ArmState;
import cyberplanner.roborio.JointOutput;
import java.util.ArrayList;
import java.util.List;

/**
 * A desktop stand-in for a mechanism of any joint count (joints by index): each joint is a
 * critically damped follower of the setpoint the robot code applies (position and velocity, the
 * way a tuned motor controller's position loop with velocity feedforward tracks it). Not a physics model: the point is that the
 * setpoints, applied as a robot applies them, bring the mechanism to each goal.
 */
public final class SimulatedMechanism {
  private static final double NATURAL_FREQUENCY_RADPS = 30.0;
  private static final double SUBSTEP_S = 0.001;

  /** One joint: position, velocity and the latest setpoint. */
  public static final class SimJoint implements JointOutput {
    double position;
    double velocity;
    double targetPosition;
    double targetVelocity;

    SimJoint(double position) {
      this.position = position;
      this.targetPosition = position;
    }

    @Override
    public void apply(double position, double velocity, double feedforwardVolts) {
      targetPosition = position;
      targetVelocity = velocity;
    }

    void placeAt(double at) {
      position = targetPosition = at;
      velocity = targetVelocity = 0;
    }

    void step(double dt) {
      double w = NATURAL_FREQUENCY_RADPS;
      double acceleration = w * w * (targetPosition - position) + 2 * w * (targetVelocity - velocity);
      velocity += acceleration * dt;
      position += velocity * dt;
    }
  }

  /** The joints by index (unmodifiable). */
  public final List<SimJoint> joints;
  private volatile List<String> pieces = List.of();

  /** At rest at these positions (m or rad), one joint per position. */
  public SimulatedMechanism(double... positions) {
    List<SimJoint> made = new ArrayList<>();
    for (double position : positions) made.add(new SimJoint(position));
    joints = List.copyOf(made);
  }

  /** At rest where the state says, holding there (a test putting the robot back). */
  public void placeAt(ArmState at) {
    for (int i = 0; i < joints.size(); ++i) joints.get(i).placeAt(at.position(i));
  }

  /** The game pieces held from now on, by name. */
  public void setPieces(List<String> held) {
    pieces = List.copyOf(held);
  }

  /** Advances the model by dtS. */
  public void step(double dtS) {
    for (double t = 0; t < dtS - 1e-12; t += SUBSTEP_S) {
      for (SimJoint joint : joints) joint.step(SUBSTEP_S);
    }
  }

  /** All joints' speeds together (m/s and rad/s, root of the sum of squares), as measured. */
  public double speed() {
    double sum = 0;
    for (SimJoint joint : joints) sum += joint.velocity * joint.velocity;
    return Math.sqrt(sum);
  }

  public ArmState state() {
    double[] positions = new double[joints.size()];
    double[] velocities = new double[joints.size()];
    for (int i = 0; i < joints.size(); ++i) {
      positions[i] = joints.get(i).position;
      velocities[i] = joints.get(i).velocity;
    }
    return ArmState.of(positions, velocities).holding(pieces);
  }
}
