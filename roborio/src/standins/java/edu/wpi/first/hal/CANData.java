package edu.wpi.first.hal;

/** STAND-IN of WPILib's CANData (signatures only; tests only). */
public class CANData {
  public final byte[] data = new byte[8];
  public int length;
  public long timestamp;
}
