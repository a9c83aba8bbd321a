package com.revrobotics.spark;

/** STAND-IN of REVLib's SparkLowLevel (its MotorType only; tests only). */
public abstract class SparkLowLevel {
  public enum MotorType {
    kBrushed,
    kBrushless
  }
}
