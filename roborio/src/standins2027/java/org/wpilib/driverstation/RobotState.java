package org.wpilib.driverstation;

/** STAND-IN of WPILib 2027's RobotState (isEnabled only; tests set it). */
public final class RobotState {
  public static boolean standInEnabled = true;

  private RobotState() {}

  public static boolean isEnabled() {
    return standInEnabled;
  }
}
