package edu.wpi.first.hal.can;

import edu.wpi.first.hal.CANStreamMessage;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;

/**
 * STAND-IN of WPILib 2026's CANJNI (the stream session methods; tests only). Tests put frames on
 * the bus with {@link #standInDeliver}; every open session whose id and mask match queues them.
 */
public class CANJNI {
  private record Session(int id, int mask, int max, ArrayDeque<long[]> frames, ArrayDeque<byte[]> data) {}

  private static final List<Session> sessions = new ArrayList<>();

  public static synchronized int openCANStreamSession(int messageID, int messageIDMask, int maxMessages) {
    sessions.add(new Session(messageID, messageIDMask, maxMessages, new ArrayDeque<>(), new ArrayDeque<>()));
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
      m.messageID = (int) head[0];
      m.timestamp = head[1];
      m.length = bytes.length;
      System.arraycopy(bytes, 0, m.data, 0, Math.min(bytes.length, m.data.length));
    }
    return n;
  }

  /** Stand-in hook: a frame on the bus, received at timestampMs (the CAN timer's ms). */
  public static synchronized void standInDeliver(int messageID, byte[] data, long timestampMs) {
    for (Session s : sessions) {
      if (s == null || (messageID & s.mask()) != (s.id() & s.mask())) continue;
      if (s.frames().size() == s.max()) continue;
      s.frames().add(new long[] {messageID, timestampMs});
      s.data().add(data.clone());
    }
  }

  public static synchronized void standInReset() {
    sessions.clear();
  }
}
