package cyberplanner.roborio;

/**
 * Everything the robot loop needs to see of cyber-planner, as plain values it polls once a loop
 * (ArmController.updateInputs): the shape of an AdvantageKit inputs class (public fields of
 * primitives, strings and their arrays, one entry per joint; logged and replayed as they are;
 * annotate a subclass with @AutoLog) and
 * a NetworkTables-free telemetry object. Written by the main loop only.
 */
public class ArmInputs {
  /** LCM is open (false: no route yet; linkError says why). */
  public boolean linkConnected;
  public String linkError = "";
  /** ARM_DAEMON_STATUS heard within 0.5 s; its age in s (+infinity before the first). */
  public boolean daemonAlive;
  public double daemonStatusAgeS = Double.POSITIVE_INFINITY;
  /** The daemon's mode (DaemonMode name, "" before any status). */
  public String daemonMode = "";
  /**
   * The daemon's joints by index with their units, as its config names them ("shoulder rad, elbow rad";
   * "" before any status). The guard compares the names with jointNames (verdict JOINTS_MISMATCH).
   */
  public String daemonJoints = "";
  /** The arm's joints by index, as the robot program named them (its ArmJoints). */
  public String[] jointNames = new String[0];
  /** The guard's verdict of the latest loop (SetpointGuard.Verdict name). */
  public String verdict = "";
  /** A team command drives the joints (manual override). */
  public boolean manualOverride;
  /** The latest move: request id (0: none yet), state (MoveState name), reason, planned s. */
  public long moveRequestId;
  public String moveState = "";
  public String moveReason = "";
  public double moveDurationS;
  /** Times the latest move's state changed, as the loop saw it (a change counter to trigger on). */
  public long moveStateChanges;
  /** Setpoint frames missing from each joint's sequence, and repeats, since start-up: by joint index. */
  public long[] lostFrames = new long[0];
  public long[] repeatedFrames = new long[0];
  /** LCM messages on our channels that did not decode. */
  public long undecodableMessages;
}
