package com.revrobotics.spark;

/** STAND-IN of REVLib's SparkFlex (its constructor; tests only). */
public class SparkFlex extends SparkBase {
  public SparkFlex(int deviceId, SparkLowLevel.MotorType type) {}
}
