package com.revrobotics.spark;

/** STAND-IN of REVLib's SparkBase (getClosedLoopController and ControlType; tests only). */
public abstract class SparkBase extends SparkLowLevel {
  public enum ControlType {
    kPosition
  }

  private final SparkClosedLoopController controller = new SparkClosedLoopController();

  public SparkClosedLoopController getClosedLoopController() {
    return controller;
  }
}
