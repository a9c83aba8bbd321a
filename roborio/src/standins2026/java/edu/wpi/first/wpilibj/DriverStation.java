package edu.wpi.first.wpilibj;

/** STAND-IN of WPILib 2026's DriverStation (isEnabled only; tests set it). */
public final class DriverStation {
  public static boolean standInEnabled = true;

  private DriverStation() {}

  public static boolean isEnabled() {
    return standInEnabled;
  }
}
