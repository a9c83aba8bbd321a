package edu.wpi.first.hal.can;

import edu.wpi.first.hal.CANStreamMessage;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;

/**
 * STAND-IN of WPILib 2026's CANJNI (the stream session methods; tests only), its signatures from
 * allwpilib branch `2026`, commit 5cffd78c06c7585a85002fac422ac8a2b04e5489. Tests put frames on the
 * bus with {@link #standInDeliver}; every open session whose id and mask match queues them. A frame
 * that finds the session's buffer full (maxMessages) is dropped, and the next read throws
 * CANStreamOverflowException with the count it copied, as the JNI's readCANStreamSession does at
 * that commit (only when it read at least one message; otherwise it returns 0). The roboRIO's
 * buffer is NetComm's, whose source is closed: this one drops as the Systemcore HAL's does (see
 * the 2027 stand-in).
 */
public class CANJNI {
  private record Session(int id, int mask, int max, ArrayDeque<long[]> frames, ArrayDeque<byte[]> data,
      boolean[] overflowed) {}

  private static final List<Session> sessions = new ArrayList<>();

  public static synchronized int openCANStreamSession(int messageID, int messageIDMask, int maxMessages) {
    sessions.add(new Session(messageID, messageIDMask, maxMessages, new ArrayDeque<>(), new ArrayDeque<>(),
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
      m.messageID = (int) head[0];
      m.timestamp = head[1];
      m.length = bytes.length;
      System.arraycopy(bytes, 0, m.data, 0, Math.min(bytes.length, m.data.length));
    }
    boolean overrun = s.overflowed()[0];
    s.overflowed()[0] = false;
    if (n > 0 && overrun) throw new CANStreamOverflowException(messages, n);
    return n;
  }

  /** Stand-in hook: a frame on the bus, received at timestampMs (the CAN timer's ms). */
  public static synchronized void standInDeliver(int messageID, byte[] data, long timestampMs) {
    for (Session s : sessions) {
      if (s == null || (messageID & s.mask()) != (s.id() & s.mask())) continue;
      if (s.frames().size() == s.max()) {
        s.overflowed()[0] = true;  // the frame is dropped; the next read says so
        continue;
      }
      s.frames().add(new long[] {messageID, timestampMs});
      s.data().add(data.clone());
    }
  }

  public static synchronized void standInReset() {
    sessions.clear();
  }
}
