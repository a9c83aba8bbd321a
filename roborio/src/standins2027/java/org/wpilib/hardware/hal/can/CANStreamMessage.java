package org.wpilib.hardware.hal.can;

/** STAND-IN of WPILib 2027's CANStreamMessage (its fields; tests only). */
public class CANStreamMessage {
  public final byte[] data = new byte[64];
  public int length;
  public int flags;
  public long timestamp;
  public int messageId;
}
