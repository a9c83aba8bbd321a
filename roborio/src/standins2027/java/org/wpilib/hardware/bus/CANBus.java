package org.wpilib.hardware.bus;

/** STAND-IN of WPILib 2027's CANBus (the Systemcore buses and their value; tests only). */
public enum CANBus {
  CAN_S0(0),
  CAN_S1(1),
  CAN_S2(2),
  CAN_S3(3),
  CAN_S4(4);

  public final int value;

  CANBus(int value) {
    this.value = value;
  }
}
