package com.ctre.phoenix6.controls;

/** STAND-IN of Phoenix 6's PositionVoltage (the builder methods the library uses; tests only). */
public class PositionVoltage {
  public double Position;
  public double Velocity;
  public double FeedForward;

  public PositionVoltage(double position) {
    Position = position;
  }

  public PositionVoltage withPosition(double newPosition) {
    Position = newPosition;
    return this;
  }

  public PositionVoltage withVelocity(double newVelocity) {
    Velocity = newVelocity;
    return this;
  }

  public PositionVoltage withFeedForward(double newFeedForward) {
    FeedForward = newFeedForward;
    return this;
  }
}
