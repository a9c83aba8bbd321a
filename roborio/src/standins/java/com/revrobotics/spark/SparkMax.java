package com.revrobotics.spark;

/** STAND-IN of REVLib's SparkMax (tests only; the real constructor also takes a motor type). */
public class SparkMax extends SparkBase {
  public SparkMax(int deviceId) {}
}
