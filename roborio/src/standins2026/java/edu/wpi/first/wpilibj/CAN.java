package edu.wpi.first.wpilibj;

/** STAND-IN of WPILib 2026's CAN class (getTimestampBaseTime only; tests set the time). */
public class CAN {
  /** Stand-in: the CAN timer, ms. */
  public static long standInTimeMs;

  public static long getTimestampBaseTime() {
    return standInTimeMs;
  }
}
