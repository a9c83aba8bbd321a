package org.wpilib.command2;

/** STAND-IN of WPILib 2027's SubsystemBase (tests only). */
public abstract class SubsystemBase implements Subsystem {}
