package cyberplanner.roborio.wpilib2026;

import cyberplanner.roborio.CanFrameRouter;
import cyberplanner.roborio.SetpointGuard;
import cyberplanner.roborio.SetpointSource;
import edu.wpi.first.hal.CANStreamMessage;
import edu.wpi.first.hal.can.CANJNI;
import edu.wpi.first.hal.can.CANStreamOverflowException;
import edu.wpi.first.wpilibj.CAN;

/**
 * Reads cyber-plannerd's frames off the roboRIO's CAN bus (WPILib 2026) through a HAL CAN stream
 * session: every frame in order, not only the newest as CAN.readPacketNew keeps it, so the guard
 * counts only real sequence gaps at any loop rate (docs/roborio.md, "Health counters"). A frame's
 * age comes from its timestamp (ms on the timer of CAN.getTimestampBaseTime()), mapped onto the
 * loop's clock, not from the time it was polled.
 */
public final class CanStreamSetpointSource implements SetpointSource, AutoCloseable {
  private static final int MAX_BUFFERED = 512;

  private final CanFrameRouter router;
  private final int session;
  private final CANStreamMessage[] batch = new CANStreamMessage[64];
  private long overruns;

  public CanStreamSetpointSource(CanFrameRouter router) {
    this.router = router;
    for (int i = 0; i < batch.length; ++i) batch[i] = new CANStreamMessage();
    session = CANJNI.openCANStreamSession(CanFrameRouter.STREAM_ID, CanFrameRouter.STREAM_MASK, MAX_BUFFERED);
  }

  /** The shipped configurations' devices: joint 0 on 1, joint 1 on 2, status 3. */
  public static CanStreamSetpointSource withReferenceDevices() {
    return new CanStreamSetpointSource(CanFrameRouter.reference());
  }

  @Override
  public void poll(SetpointGuard guard, long nowMicros) {
    long baseMs = CAN.getTimestampBaseTime();
    int read;
    do {
      try {
        read = CANJNI.readCANStreamSession(session, batch, batch.length);
      } catch (CANStreamOverflowException e) {
        overruns++;  // frames were dropped before we read them; the guard sees the gap
        read = e.getMessagesRead();
      }
      for (int i = 0; i < read; ++i) {
        CANStreamMessage m = batch[i];
        long ageMicros = Math.max(0, baseMs - m.timestamp) * 1000;
        router.offer(guard, m.messageID, m.data, m.length, nowMicros - ageMicros);
      }
    } while (read == batch.length);
  }

  public CanFrameRouter router() {
    return router;
  }

  /** Reads in which the session's buffer had overflowed. */
  public long overruns() {
    return overruns;
  }

  @Override
  public void close() {
    CANJNI.closeCANStreamSession(session);
  }
}
