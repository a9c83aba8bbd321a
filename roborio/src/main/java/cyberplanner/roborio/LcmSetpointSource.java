package cyberplanner.roborio;

import cyberplanner.arm_setpoint_t;
import cyberplanner.roborio.can.DaemonMode;
import cyberplanner.roborio.can.Setpoint;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.function.LongSupplier;

/**
 * Desktop simulation, or a daemon on the robot controller itself: the setpoints from ARM_SETPOINT
 * instead of CAN. The daemon must publish every stream tick (`setpoint_echo_full_rate = true`,
 * docs/configuration.md); the message's mode stands in for the status frame. Every message is
 * queued with its time of receipt (the daemon's utime is another clock), so the guard sees every
 * sequence number whatever the poll rate, and a setpoint's age counts from its arrival, not from
 * the poll. Joints by index (position[i], velocity[i], volts[i], sequence[i]), as many as the
 * guard's; a message of another num_joints is not this arm's and is ignored. Device numbers are not
 * on LCM: the setpoints carry device -1.
 */
public final class LcmSetpointSource implements SetpointSource {
  private static final int MAX_QUEUED = 1000;

  private record Received(arm_setpoint_t message, long micros) {}

  private final ConcurrentLinkedQueue<Received> queue = new ConcurrentLinkedQueue<>();

  /** @param clockMicros the robot loop's clock (the one ArmController is given), in microseconds */
  public LcmSetpointSource(CyberPlannerClient client, LongSupplier clockMicros) {
    client.setSetpointListener(message -> {
      queue.add(new Received(message, clockMicros.getAsLong()));
      // A loop that stopped polling must not grow the queue without bound: the oldest go.
      while (queue.size() > MAX_QUEUED) queue.poll();
    });
  }

  /** With the System.nanoTime clock, ArmController's default. */
  public LcmSetpointSource(CyberPlannerClient client) {
    this(client, () -> System.nanoTime() / 1000);
  }

  @Override
  public void poll(SetpointGuard guard, long nowMicros) {
    for (Received r; (r = queue.poll()) != null; ) {
      DaemonMode mode = DaemonMode.fromWire(r.message.mode);
      if (mode == null) continue;
      arm_setpoint_t m = r.message;
      // Another robot's joint count: not ours to follow (ignored; the guard goes stale). LCM's
      // decoder sizes every array by num_joints.
      if (m.num_joints != guard.joints().count()) continue;
      guard.onStatus(mode, r.micros);
      for (int i = 0; i < m.num_joints; ++i) {
        guard.onSetpoint(i, new Setpoint(-1, m.position[i], m.velocity[i], m.volts[i], m.sequence[i] & 0xFF),
            r.micros);
      }
    }
  }
}
