package edu.wpi.first.hal;

/** STAND-IN of WPILib 2026's CANStreamMessage (its fields; tests only). */
public class CANStreamMessage {
  public final byte[] data = new byte[8];
  public int length;
  public long timestamp;
  public int messageID;
}
