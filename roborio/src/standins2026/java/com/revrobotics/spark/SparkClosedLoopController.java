package com.revrobotics.spark;

import com.revrobotics.REVLibError;

/** STAND-IN of REVLib's SparkClosedLoopController (setSetpoint only; tests read the fields). */
public class SparkClosedLoopController {
  public enum ArbFFUnits {
    kVoltage
  }

  public double standInValue = Double.NaN;
  public double standInArbFeedforward = Double.NaN;
  public SparkBase.ControlType standInControlType;
  public ClosedLoopSlot standInSlot;
  public ArbFFUnits standInArbFFUnits;

  public REVLibError setSetpoint(double setpoint, SparkBase.ControlType ctrl, ClosedLoopSlot slot, double arbFeedforward,
      ArbFFUnits arbFFUnits) {
    standInValue = setpoint;
    standInControlType = ctrl;
    standInSlot = slot;
    standInArbFeedforward = arbFeedforward;
    standInArbFFUnits = arbFFUnits;
    return REVLibError.kOk;
  }
}
