package edu.wpi.first.wpilibj2.command;

/** STAND-IN of WPILib's SubsystemBase (tests only). */
public abstract class SubsystemBase implements Subsystem {}
