package cyberplanner.roborio;

import cyberplanner.roborio.can.DaemonMode;
import cyberplanner.roborio.can.Setpoint;
import java.util.List;

/**
 * Decides whether the robot may apply cyber-plannerd's setpoints now (docs/roborio.md, "Safety").
 * It is fed setpoints of each joint of its JointChain, by index (CAN frames or ARM_SETPOINT), and
 * the daemon's status (the CAN status frame or ARM_DAEMON_STATUS) with the robot's own clock, and
 * checks the sequence bytes and the ages:
 * a setpoint older than its limit, a daemon not heard from, a daemon that does not stream (no
 * state, fault, robot disabled) or one whose joints are not these all mean "stop using
 * cyber-planner setpoints".
 * Not thread-safe: call from the robot's main loop.
 */
public final class SetpointGuard {
  /** What {@link #verdict} says, in the order it checks. */
  public enum Verdict {
    /** Fresh setpoints of every joint from a streaming daemon: apply them. */
    USE,
    /** No status from the daemon yet, or none within the status age limit. */
    DAEMON_LOST,
    /** The daemon reports no state, a fault or a disabled robot: it sends no setpoints. */
    DAEMON_NOT_STREAMING,
    /**
     * The daemon's joints (the joint_names of its ARM_DAEMON_STATUS) are not the guard's, by name
     * and in order: its setpoints are for another mechanism, or the robot program wired its joints
     * in another order.
     */
    JOINTS_MISMATCH,
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
  private final JointChain joints;
  private final JointTrack[] tracks;
  private DaemonMode mode;
  private long statusMicros;
  private List<String> daemonJoints = List.of();

  /** The defaults: 50 ms setpoint age, 250 ms status age. */
  public SetpointGuard(JointChain joints) {
    this(joints, 0.05, 0.25);
  }

  /**
   * @param joints the arm's joints: the verdict is USE only with a fresh setpoint of each
   * @param maxSetpointAgeS a setpoint older than this is not applied (the daemon streams at
   *     200 Hz: 0.05 s tolerates several lost frames)
   * @param maxStatusAgeS the daemon is lost when its status is older than this (10 Hz: 0.25 s)
   */
  public SetpointGuard(JointChain joints, double maxSetpointAgeS, double maxStatusAgeS) {
    if (joints == null) throw new IllegalArgumentException("joints is null");
    if (!(maxSetpointAgeS > 0) || !(maxStatusAgeS > 0)) {
      throw new IllegalArgumentException("age limits must be positive");
    }
    this.maxSetpointAgeMicros = Math.round(maxSetpointAgeS * 1e6);
    this.maxStatusAgeMicros = Math.round(maxStatusAgeS * 1e6);
    this.joints = joints;
    this.tracks = new JointTrack[joints.count()];
    for (int i = 0; i < tracks.length; ++i) tracks[i] = new JointTrack();
  }

  /**
   * The daemon's joints, by name in chain order (ARM_DAEMON_STATUS joint_names; CyberPlannerClient
   * daemonJointNames()); empty while none is known, which checks nothing (the CAN status frame has
   * no names). ArmController feeds it every loop.
   */
  public void onDaemonJoints(List<String> names) {
    daemonJoints = names == null ? List.of() : names;
  }

  /** The daemon's joints as last fed by onDaemonJoints (empty: unknown). */
  public List<String> daemonJoints() {
    return daemonJoints;
  }

  /** The daemon's mode, received at nowMicros. */
  public void onStatus(DaemonMode mode, long nowMicros) {
    this.mode = mode;
    this.statusMicros = nowMicros;
  }

  /** The joints it guards. */
  public JointChain joints() {
    return joints;
  }

  /**
   * A setpoint of joint index, received at nowMicros. Returns false for a repeat of the latest
   * sequence number (ignored); a gap in the sequence counts the frames lost. An index that is not a
   * joint's throws IllegalArgumentException (a source wired for other joints: ArmController checks
   * that when it is built).
   */
  public boolean onSetpoint(int joint, Setpoint setpoint, long nowMicros) {
    JointTrack track = tracks[joints.checkIndex(joint)];
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
    if (!daemonJoints.isEmpty() && !daemonJoints.equals(joints.names())) return Verdict.JOINTS_MISMATCH;
    for (JointTrack track : tracks) {
      if (track.latest == null || nowMicros - track.receivedMicros > maxSetpointAgeMicros) {
        return Verdict.SETPOINT_STALE;
      }
    }
    return Verdict.USE;
  }

  /** The latest setpoint of joint index, or null; apply it only when {@link #verdict} is USE. */
  public Setpoint latest(int joint) {
    return tracks[joints.checkIndex(joint)].latest;
  }

  /** The latest setpoint of the joint of this name, or null. */
  public Setpoint latest(String joint) {
    return latest(joints.index(joint));
  }

  /** The daemon's latest mode, or null before any status. */
  public DaemonMode mode() {
    return mode;
  }

  /** Frames missing from the sequence of joint index since start-up. */
  public long lostFrames(int joint) {
    return tracks[joints.checkIndex(joint)].lostFrames;
  }

  /** Frames missing from the sequence of the joint of this name since start-up. */
  public long lostFrames(String joint) {
    return lostFrames(joints.index(joint));
  }

  /** Frames that repeated the latest sequence number of joint index. */
  public long repeatedFrames(int joint) {
    return tracks[joints.checkIndex(joint)].repeatedFrames;
  }

  /** Frames that repeated the latest sequence number of the joint of this name. */
  public long repeatedFrames(String joint) {
    return repeatedFrames(joints.index(joint));
  }
}
