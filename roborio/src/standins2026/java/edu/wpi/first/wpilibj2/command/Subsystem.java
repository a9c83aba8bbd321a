package edu.wpi.first.wpilibj2.command;

/** STAND-IN of WPILib's command-based Subsystem (signatures used only; tests only). */
public interface Subsystem {
  default void periodic() {}
}
