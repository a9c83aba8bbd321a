package edu.wpi.first.wpilibj;

import edu.wpi.first.hal.CANData;
import java.util.ArrayDeque;
import java.util.HashMap;
import java.util.Map;

/**
 * STAND-IN of WPILib's CAN class (the constructor and the read methods the library uses; tests
 * only). Tests deliver packets with the static stand-in hook {@link #standInDeliver}.
 */
public class CAN {
  private static final Map<Long, ArrayDeque<byte[]>> pending = new HashMap<>();
  private final int deviceId;
  private final int manufacturer;
  private final int deviceType;

  public CAN(int deviceId, int deviceManufacturer, int deviceType) {
    this.deviceId = deviceId;
    this.manufacturer = deviceManufacturer;
    this.deviceType = deviceType;
  }

  private static long key(int deviceType, int manufacturer, int apiId, int deviceId) {
    return ((long) deviceType << 40) | ((long) manufacturer << 24) | ((long) apiId << 8) | deviceId;
  }

  /** Stand-in hook: a packet arrives for (deviceType, manufacturer, apiId, deviceId). */
  public static synchronized void standInDeliver(int deviceType, int manufacturer, int apiId, int deviceId, byte[] data) {
    pending.computeIfAbsent(key(deviceType, manufacturer, apiId, deviceId), k -> new ArrayDeque<>()).add(data.clone());
  }

  public static synchronized void standInReset() {
    pending.clear();
  }

  /** True only for a packet not read before (here: the newest queued one; older are dropped). */
  public boolean readPacketNew(int apiId, CANData data) {
    synchronized (CAN.class) {
      ArrayDeque<byte[]> queue = pending.get(key(deviceType, manufacturer, apiId, deviceId));
      if (queue == null || queue.isEmpty()) return false;
      byte[] newest = queue.peekLast();
      queue.clear();
      System.arraycopy(newest, 0, data.data, 0, Math.min(8, newest.length));
      data.length = newest.length;
      return true;
    }
  }
}
