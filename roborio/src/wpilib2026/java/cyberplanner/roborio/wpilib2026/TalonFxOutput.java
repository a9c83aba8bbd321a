package cyberplanner.roborio.wpilib2026;

import com.ctre.phoenix6.controls.PositionVoltage;
import com.ctre.phoenix6.hardware.TalonFX;
import cyberplanner.roborio.JointOutput;

/**
 * Applies a setpoint to a Phoenix 6 TalonFX as PositionVoltage with velocity and feedforward. The
 * TalonFX works in mechanism rotations (after its SensorToMechanismRatio): rotationsPerUnit turns
 * the joint's m or rad into them.
 */
public final class TalonFxOutput implements JointOutput {
  private final TalonFX motor;
  private final double rotationsPerUnit;
  private final PositionVoltage request = new PositionVoltage(0);

  public TalonFxOutput(TalonFX motor, double rotationsPerUnit) {
    this.motor = motor;
    this.rotationsPerUnit = rotationsPerUnit;
  }

  @Override
  public void apply(double position, double velocity, double feedforwardVolts) {
    motor.setControl(request.withPosition(position * rotationsPerUnit).withVelocity(velocity * rotationsPerUnit)
        .withFeedForward(feedforwardVolts));
  }
}
