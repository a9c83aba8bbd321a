package cyberplanner.roborio.sim;

import cyberplanner.roborio.ArmState;
import cyberplanner.roborio.JointOutput;
import java.util.List;

/**
 * A desktop stand-in for a two-joint mechanism (joint 0 and joint 1 by index): each joint is a
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

  public final SimJoint joint0;
  public final SimJoint joint1;
  private volatile List<String> pieces = List.of();

  /** At rest at these positions (m or rad). */
  public SimulatedMechanism(double joint0Position, double joint1Position) {
    joint0 = new SimJoint(joint0Position);
    joint1 = new SimJoint(joint1Position);
  }

  /** At rest at these positions, holding there (a test putting the robot back). */
  public void placeAt(double joint0Position, double joint1Position) {
    joint0.placeAt(joint0Position);
    joint1.placeAt(joint1Position);
  }

  /** The game pieces held from now on, by name. */
  public void setPieces(List<String> held) {
    pieces = List.copyOf(held);
  }

  /** Advances the model by dtS. */
  public void step(double dtS) {
    for (double t = 0; t < dtS - 1e-12; t += SUBSTEP_S) {
      joint0.step(SUBSTEP_S);
      joint1.step(SUBSTEP_S);
    }
  }

  /** Both joints' speeds together (m/s and rad/s), as measured. */
  public double speed() {
    return Math.hypot(joint0.velocity, joint1.velocity);
  }

  public ArmState state() {
    return new ArmState(joint0.position, joint0.velocity, joint1.position, joint1.velocity, pieces);
  }
}
