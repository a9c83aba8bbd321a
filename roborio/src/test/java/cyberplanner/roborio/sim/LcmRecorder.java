package cyberplanner.roborio.sim;

import cyberplanner.arm_cancel_t;
import cyberplanner.arm_plan_status_t;
import cyberplanner.arm_setpoint_t;
import java.io.IOException;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import lcm.lcm.LCM;
import lcm.lcm.LCMDataInputStream;

/**
 * What goes over the daemon's channels, seen from an LCM instance of its own (a tool such as
 * lcm-spy would see the same): the setpoint echo, the cancels anyone sends and the goals' statuses.
 */
final class LcmRecorder implements AutoCloseable {
  private interface Decoder<T> {
    T decode(LCMDataInputStream in) throws IOException;
  }

  private final LCM lcm;
  final List<arm_setpoint_t> setpoints = new CopyOnWriteArrayList<>();
  final List<arm_cancel_t> cancels = new CopyOnWriteArrayList<>();
  final List<arm_plan_status_t> statuses = new CopyOnWriteArrayList<>();

  LcmRecorder(String url) throws IOException {
    lcm = new LCM(url);
    record("ARM_SETPOINT", setpoints, arm_setpoint_t::new);
    record("ARM_CANCEL", cancels, arm_cancel_t::new);
    record("ARM_PLAN_STATUS", statuses, arm_plan_status_t::new);
  }

  private <T> void record(String channel, List<T> into, Decoder<T> decoder) {
    lcm.subscribe(channel, (l, c, in) -> {
      try {
        into.add(decoder.decode(in));
      } catch (IOException e) {
        throw new AssertionError(channel + ": " + e);
      }
    });
  }

  /** This machine's wall clock, µs: the daemon's utime (docs/lcm.md, "Times"). */
  static long wallMicros() {
    Instant now = Instant.now();
    return now.getEpochSecond() * 1_000_000 + now.getNano() / 1000;
  }

  void clear() {
    setpoints.clear();
    cancels.clear();
    statuses.clear();
  }

  /** How far into its trajectory the latest echo of a moving request is, s (0 before one). */
  double trajectoryTimeS(long requestId) {
    double t = 0;
    for (arm_setpoint_t s : setpoints) {
      if (s.request_id == requestId && s.mode == arm_setpoint_t.MODE_MOVING) t = s.trajectory_t_s;
    }
    return t;
  }

  /** The first echo of a request, or null. */
  arm_setpoint_t firstSetpointOf(long requestId) {
    for (arm_setpoint_t s : setpoints) {
      if (s.request_id == requestId) return s;
    }
    return null;
  }

  /** The echoes before the first of a request (all of them if it has none). */
  List<arm_setpoint_t> setpointsBefore(long requestId) {
    List<arm_setpoint_t> out = new ArrayList<>();
    for (arm_setpoint_t s : setpoints) {
      if (s.request_id == requestId) break;
      out.add(s);
    }
    return out;
  }

  /** When the daemon published that status of a request (its utime), waiting up to 2 s; 0 if never. */
  long statusMicros(long requestId, byte status) throws InterruptedException {
    for (int i = 0; i < 200; ++i) {
      for (arm_plan_status_t s : statuses) {
        if (s.request_id == requestId && s.status == status) return s.utime;
      }
      Thread.sleep(10);
    }
    return 0;
  }

  @Override
  public void close() {
    lcm.close();
  }
}
