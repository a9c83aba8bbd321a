package org.wpilib.command2;

/** STAND-IN of WPILib 2027's command-based (org.wpilib.command2) Subsystem (signatures used only; tests only). */
public interface Subsystem {
  default void periodic() {}
}
