package cyberplanner.roborio.sim;

import cyberplanner.roborio.ArmState;
import cyberplanner.roborio.JointOutput;

/**
 * A desktop stand-in for the elevator and arm: each joint is a critically damped follower of the
 * setpoint the robot code applies (position and velocity, the way a tuned motor controller's
 * position loop with velocity feedforward tracks it). Not a physics model: the point is that the
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

  public final SimJoint elevator;
  public final SimJoint arm;
  private volatile boolean heldCoral;
  private volatile boolean heldAlgae;

  public SimulatedMechanism(double elevatorM, double armRad) {
    elevator = new SimJoint(elevatorM);
    arm = new SimJoint(armRad);
  }

  /** At rest at elevatorM, armRad, holding there (a test putting the robot back). */
  public void placeAt(double elevatorM, double armRad) {
    elevator.placeAt(elevatorM);
    arm.placeAt(armRad);
  }

  public void setPieces(boolean coral, boolean algae) {
    heldCoral = coral;
    heldAlgae = algae;
  }

  /** Advances the model by dtS. */
  public void step(double dtS) {
    for (double t = 0; t < dtS - 1e-12; t += SUBSTEP_S) {
      elevator.step(SUBSTEP_S);
      arm.step(SUBSTEP_S);
    }
  }

  public ArmState state() {
    return new ArmState(elevator.position, elevator.velocity, arm.position, arm.velocity, heldCoral, heldAlgae);
  }
}
