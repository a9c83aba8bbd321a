package org.wpilib.hardware.hal.can;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;

/**
 * STAND-IN of WPILib 2027's CANJNI (the stream session methods; tests only), its signatures from
 * allwpilib `main`, commit caf0fb2dccb462a1507888246646daa5ba38cd82. Tests put frames on the bus
 * with {@link #standInDeliver}; every open session whose id and mask match queues them. As the
 * Systemcore HAL's session at that commit (CANStreamStorage::CheckFrame and
 * HAL_CAN_ReadStreamSession in hal/src/main/native/systemcore), a frame that finds the buffer
 * full (maxMessages) is dropped and flags the session; the next read clears the flag and, as the
 * JNI's readCANStreamSession does, throws CANStreamOverflowException with the count it copied
 * when it read at least one message (otherwise it returns 0).
 */
public class CANJNI {
  private record Session(int id, int mask, int max, ArrayDeque<long[]> frames, ArrayDeque<byte[]> data,
      boolean[] overflowed) {}

  private static final List<Session> sessions = new ArrayList<>();
  /** Stand-in: the bus of every session opened. */
  public static final List<Integer> standInBuses = new ArrayList<>();

  public static synchronized int openCANStreamSession(int busId, int messageId, int messageIDMask, int maxMessages) {
    standInBuses.add(busId);
    sessions.add(new Session(messageId, messageIDMask, maxMessages, new ArrayDeque<>(), new ArrayDeque<>(),
        new boolean[1]));
    return sessions.size();
  }

  public static synchronized void closeCANStreamSession(int sessionHandle) {
    sessions.set(sessionHandle - 1, null);
  }

  public static synchronized int readCANStreamSession(int sessionHandle, CANStreamMessage[] messages,
      int messagesToRead) throws CANStreamOverflowException {
    Session s = sessions.get(sessionHandle - 1);
    int n = 0;
    while (n < messagesToRead && !s.frames().isEmpty()) {
      long[] head = s.frames().poll();
      byte[] bytes = s.data().poll();
      CANStreamMessage m = messages[n++];
      m.messageId = (int) head[0];
      m.timestamp = head[1];
      m.length = bytes.length;
      System.arraycopy(bytes, 0, m.data, 0, Math.min(bytes.length, m.data.length));
    }
    boolean overrun = s.overflowed()[0];
    s.overflowed()[0] = false;
    if (n > 0 && overrun) throw new CANStreamOverflowException(messages, n);
    return n;
  }

  /** Stand-in hook: a frame on the bus, received at timestampMicros (the robot clock). */
  public static synchronized void standInDeliver(int messageID, byte[] data, long timestampMicros) {
    for (Session s : sessions) {
      if (s == null || (messageID & s.mask()) != (s.id() & s.mask())) continue;
      if (s.frames().size() == s.max()) {
        s.overflowed()[0] = true;  // the frame is dropped; the next read says so
        continue;
      }
      s.frames().add(new long[] {messageID, timestampMicros});
      s.data().add(data.clone());
    }
  }

  public static synchronized void standInReset() {
    sessions.clear();
    standInBuses.clear();
  }
}
