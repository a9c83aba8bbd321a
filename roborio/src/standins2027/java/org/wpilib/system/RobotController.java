package org.wpilib.system;

/** STAND-IN of WPILib 2027's RobotController (getTime only; tests set it). */
public final class RobotController {
  public static long standInTimeMicros;

  private RobotController() {}

  public static long getTime() {
    return standInTimeMicros;
  }
}
