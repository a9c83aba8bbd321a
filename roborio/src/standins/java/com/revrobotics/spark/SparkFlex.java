package com.revrobotics.spark;

/** STAND-IN of REVLib's SparkFlex (tests only; the real constructor also takes a motor type). */
public class SparkFlex extends SparkBase {
  public SparkFlex(int deviceId) {}
}
