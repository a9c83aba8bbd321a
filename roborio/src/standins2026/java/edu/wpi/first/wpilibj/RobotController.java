package edu.wpi.first.wpilibj;

/** STAND-IN of WPILib 2026's RobotController (getFPGATime only; tests set it). */
public final class RobotController {
  public static long standInFpgaTimeMicros;

  private RobotController() {}

  public static long getFPGATime() {
    return standInFpgaTimeMicros;
  }
}
