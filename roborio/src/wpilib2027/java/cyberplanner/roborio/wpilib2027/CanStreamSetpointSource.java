package cyberplanner.roborio.wpilib2027;

import cyberplanner.roborio.CanFrameRouter;
import cyberplanner.roborio.SetpointGuard;
import cyberplanner.roborio.SetpointSource;
import org.wpilib.hardware.bus.CANBus;
import org.wpilib.hardware.hal.can.CANJNI;
import org.wpilib.hardware.hal.can.CANStreamMessage;
import org.wpilib.hardware.hal.can.CANStreamOverflowException;
import org.wpilib.system.RobotController;

/**
 * Reads cyber-plannerd's frames off one of the Systemcore's CAN buses (WPILib 2027; the daemon's
 * adapter is wired to it, e.g. CANBus.CAN_S0) through a HAL CAN stream session: every frame in
 * order, not only the newest as CAN.readPacketNew/readPacketTimeout keep it, so the guard counts
 * only real sequence gaps at any loop rate (docs/roborio.md, "Health counters"). A frame's age
 * comes from its timestamp (µs on the robot clock, RobotController.getTime()), mapped onto the
 * loop's clock, not from the time it was polled.
 */
public final class CanStreamSetpointSource implements SetpointSource, AutoCloseable {
  private static final int MAX_BUFFERED = 512;

  private final CanFrameRouter router;
  private final int session;
  private final CANStreamMessage[] batch = new CANStreamMessage[64];
  private long overruns;

  public CanStreamSetpointSource(CANBus bus, CanFrameRouter router) {
    this.router = router;
    for (int i = 0; i < batch.length; ++i) batch[i] = new CANStreamMessage();
    session = CANJNI.openCANStreamSession(bus.value, CanFrameRouter.STREAM_ID, CanFrameRouter.STREAM_MASK,
        MAX_BUFFERED);
  }

  /** The shipped configurations' devices (joint 0 on 1, joint 1 on 2, status 3) on bus. */
  public static CanStreamSetpointSource withReferenceDevices(CANBus bus) {
    return new CanStreamSetpointSource(bus, CanFrameRouter.reference());
  }

  @Override
  public void poll(SetpointGuard guard, long nowMicros) {
    long robotMicros = RobotController.getTime();
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
        long ageMicros = Math.max(0, robotMicros - m.timestamp);
        router.offer(guard, m.messageId, m.data, m.length, nowMicros - ageMicros);
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
