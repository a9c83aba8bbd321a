package cyberplanner.roborio;

import cyberplanner.roborio.can.DaemonMode;
import cyberplanner.roborio.can.Setpoint;

/**
 * Decides whether the robot may apply cyber-plannerd's setpoints now (docs/roborio.md, "Safety").
 * It is fed setpoints (CAN frames or ARM_SETPOINT) and the daemon's status (the CAN status frame
 * or ARM_DAEMON_STATUS) with the robot's own clock, and checks the sequence bytes and the ages:
 * a setpoint older than its limit, a daemon not heard from, or a daemon that does not stream
 * (no state, fault, robot disabled) all mean "stop using cyber-planner setpoints".
 * Not thread-safe: call from the robot's main loop.
 */
public final class SetpointGuard {
  /** What {@link #verdict} says, in the order it checks. */
  public enum Verdict {
    /** Fresh setpoints of both joints from a streaming daemon: apply them. */
    USE,
    /** No status from the daemon yet, or none within the status age limit. */
    DAEMON_LOST,
    /** The daemon reports no state, a fault or a disabled robot: it sends no setpoints. */
    DAEMON_NOT_STREAMING,
    /** A joint has had no setpoint yet, or none within the setpoint age limit. */
    SETPOINT_STALE
  }

  private static final class JointTrack {
    Setpoint latest;
    long receivedMicros;
    long lostFrames;
    long repeatedFrames;
  }

  private final long maxSetpointAgeMicros;
  private final long maxStatusAgeMicros;
  private final JointTrack[] joints = new JointTrack[Joint.COUNT];
  private DaemonMode mode;
  private long statusMicros;

  /**
   * @param maxSetpointAgeS a setpoint older than this is not applied (the daemon streams at
   *     200 Hz: 0.05 s tolerates several lost frames)
   * @param maxStatusAgeS the daemon is lost when its status is older than this (10 Hz: 0.25 s)
   */
  public SetpointGuard(double maxSetpointAgeS, double maxStatusAgeS) {
    if (!(maxSetpointAgeS > 0) || !(maxStatusAgeS > 0)) {
      throw new IllegalArgumentException("age limits must be positive");
    }
    this.maxSetpointAgeMicros = Math.round(maxSetpointAgeS * 1e6);
    this.maxStatusAgeMicros = Math.round(maxStatusAgeS * 1e6);
    for (int i = 0; i < joints.length; ++i) joints[i] = new JointTrack();
  }

  /** The daemon's mode, received at nowMicros. */
  public void onStatus(DaemonMode mode, long nowMicros) {
    this.mode = mode;
    this.statusMicros = nowMicros;
  }

  /**
   * A setpoint of one joint, received at nowMicros. Returns false for a repeat of the latest
   * sequence number (ignored); a gap in the sequence counts the frames lost.
   */
  public boolean onSetpoint(Joint joint, Setpoint setpoint, long nowMicros) {
    JointTrack track = joints[joint.index()];
    if (track.latest != null) {
      int step = (setpoint.sequence() - track.latest.sequence()) & 0xFF;
      if (step == 0) {
        track.repeatedFrames++;
        return false;
      }
      track.lostFrames += step - 1;
    }
    track.latest = setpoint;
    track.receivedMicros = nowMicros;
    return true;
  }

  public Verdict verdict(long nowMicros) {
    if (mode == null || nowMicros - statusMicros > maxStatusAgeMicros) return Verdict.DAEMON_LOST;
    if (!mode.streams()) return Verdict.DAEMON_NOT_STREAMING;
    for (JointTrack track : joints) {
      if (track.latest == null || nowMicros - track.receivedMicros > maxSetpointAgeMicros) return Verdict.SETPOINT_STALE;
    }
    return Verdict.USE;
  }

  /** The latest setpoint of a joint, or null; apply it only when {@link #verdict} is USE. */
  public Setpoint latest(Joint joint) {
    return joints[joint.index()].latest;
  }

  /** The daemon's latest mode, or null before any status. */
  public DaemonMode mode() {
    return mode;
  }

  /** Frames missing from the sequence of a joint since start-up. */
  public long lostFrames(Joint joint) {
    return joints[joint.index()].lostFrames;
  }

  /** Frames that repeated the latest sequence number of a joint. */
  public long repeatedFrames(Joint joint) {
    return joints[joint.index()].repeatedFrames;
  }
}
