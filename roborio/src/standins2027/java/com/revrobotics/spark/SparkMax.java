package com.revrobotics.spark;

/** STAND-IN of REVLib's SparkMax (its constructor; tests only). */
public class SparkMax extends SparkBase {
  public SparkMax(int deviceId, SparkLowLevel.MotorType type) {}
}
