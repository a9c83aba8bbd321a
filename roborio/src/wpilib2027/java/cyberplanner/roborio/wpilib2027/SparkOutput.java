package cyberplanner.roborio.wpilib2027;

import com.revrobotics.spark.ClosedLoopSlot;
import com.revrobotics.spark.SparkBase;
import com.revrobotics.spark.SparkClosedLoopController.ArbFFUnits;
import com.revrobotics.spark.SparkClosedLoopController;
import cyberplanner.roborio.JointOutput;

/**
 * Applies a setpoint to a REVLib SparkMax or SparkFlex: position control with the feedforward as
 * an arbitrary feedforward in volts (the velocity has no input in REV's position mode), through
 * setSetpoint (REVLib 2027 drops setReference). The Spark works in its encoder's units after the position
 * conversion factor: unitsPerJointUnit turns the joint's m or rad into them.
 */
public final class SparkOutput implements JointOutput {
  private final SparkClosedLoopController controller;
  private final double unitsPerJointUnit;
  private final ClosedLoopSlot slot;

  public SparkOutput(SparkBase spark, double unitsPerJointUnit, ClosedLoopSlot slot) {
    this.controller = spark.getClosedLoopController();
    this.unitsPerJointUnit = unitsPerJointUnit;
    this.slot = slot;
  }

  @Override
  public void apply(double position, double velocity, double feedforwardVolts) {
    controller.setSetpoint(position * unitsPerJointUnit, SparkBase.ControlType.kPosition, slot, feedforwardVolts,
        ArbFFUnits.kVoltage);
  }
}
