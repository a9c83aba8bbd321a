package com.ctre.phoenix6;

/** STAND-IN of Phoenix 6's CANBus (a constructor for the tests' TalonFX; tests only). */
public class CANBus {
  public CANBus(String canbus) {}
}
