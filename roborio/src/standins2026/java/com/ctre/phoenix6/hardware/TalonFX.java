package com.ctre.phoenix6.hardware;

import com.ctre.phoenix6.StatusCode;
import com.ctre.phoenix6.controls.PositionVoltage;

/** STAND-IN of Phoenix 6's TalonFX (setControl only; tests read the standIn fields). */
public class TalonFX {
  public double standInPosition = Double.NaN;
  public double standInVelocity = Double.NaN;
  public double standInFeedForward = Double.NaN;

  public TalonFX(int deviceId) {}

  public StatusCode setControl(PositionVoltage request) {
    standInPosition = request.Position;
    standInVelocity = request.Velocity;
    standInFeedForward = request.FeedForward;
    return StatusCode.OK;
  }
}
