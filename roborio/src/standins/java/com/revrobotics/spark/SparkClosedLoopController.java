package com.revrobotics.spark;

import com.revrobotics.REVLibError;

/** STAND-IN of REVLib's SparkClosedLoopController (setReference only; tests read the fields). */
public class SparkClosedLoopController {
  public enum ArbFFUnits {
    kVoltage
  }

  public double standInValue = Double.NaN;
  public double standInArbFeedforward = Double.NaN;
  public SparkBase.ControlType standInControlType;
  public ClosedLoopSlot standInSlot;
  public ArbFFUnits standInArbFFUnits;

  public REVLibError setReference(double value, SparkBase.ControlType ctrl, ClosedLoopSlot slot, double arbFeedforward,
      ArbFFUnits arbFFUnits) {
    standInValue = value;
    standInControlType = ctrl;
    standInSlot = slot;
    standInArbFeedforward = arbFeedforward;
    standInArbFFUnits = arbFFUnits;
    return REVLibError.kOk;
  }
}
