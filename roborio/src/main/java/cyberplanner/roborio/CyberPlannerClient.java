package cyberplanner.roborio;

import cyberplanner.arm_cancel_t;
import cyberplanner.arm_daemon_status_t;
import cyberplanner.arm_goal_t;
import cyberplanner.arm_plan_status_t;
import cyberplanner.arm_setpoint_t;
import cyberplanner.arm_state_t;
import cyberplanner.roborio.can.DaemonMode;
import java.io.IOException;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import lcm.lcm.LCM;
import lcm.lcm.LCMDataInputStream;
import lcm.lcm.LCMEncodable;
import lcm.lcm.LCMSubscriber;

/**
 * The robot's side of cyber-plannerd's LCM interface (docs/lcm.md): publishes ARM_STATE, sends
 * goals with a request id each and tracks their ARM_PLAN_STATUS, cancels them on ARM_CANCEL, and
 * watches ARM_DAEMON_STATUS for the daemon's liveness and mode. Ages are measured with this
 * machine's monotonic clock at receipt (the daemon's utime is another machine's clock). It starts
 * without a network and connects when one appears (LcmLink). Thread-safe; LCM delivers on its own
 * thread.
 */
public final class CyberPlannerClient implements AutoCloseable {
  /**
   * The robot LAN: one hop, port 5810, inside the team-use range 5800-5810 that field rules allow
   * (5800-5809 are Limelight's and PhotonVision's; docs/lcm.md).
   */
  public static final String ROBOT_LAN_URL = "udpm://239.255.76.67:5810?ttl=1";
  /** How often a client without a route tries to open LCM again. */
  public static final double RETRY_S = 1.0;

  private static final long MAX_OPEN_MOVES = 1000;

  private final LcmLink link;
  private final Channels channels;
  private final AtomicLong nextRequestId;
  private final Map<Long, MoveHandle> moves = new ConcurrentHashMap<>();
  private volatile arm_daemon_status_t daemonStatus;
  private volatile List<String> daemonJointNames = List.of();
  private volatile long daemonStatusNanos;
  private volatile Consumer<arm_setpoint_t> setpointListener;
  private final AtomicLong undecodable = new AtomicLong();

  /** LCM at url, opened now or, without a route, later; request ids start at 1. Never throws. */
  public CyberPlannerClient(String url) {
    this(() -> new LCM(url), Channels.DEFAULT, 1);
  }

  /** An LCM instance already open (tests: memq://). */
  public CyberPlannerClient(LCM lcm, Channels channels, long firstRequestId) {
    this(() -> lcm, channels, firstRequestId);
  }

  /**
   * @param firstRequestId the first move's request id; the next ones count up (a robot program
   *     that restarts may start from, e.g., the time, so old answers are not taken for new moves)
   */
  public CyberPlannerClient(LcmLink.Opener opener, Channels channels, long firstRequestId) {
    this.channels = channels;
    this.nextRequestId = new AtomicLong(firstRequestId);
    this.link = new LcmLink(opener, RETRY_S, System::nanoTime, this::subscribe);
    link.get();
  }

  private void subscribe(LCM lcm) {
    lcm.subscribe(channels.planStatus(), subscriber(this::onPlanStatus));
    lcm.subscribe(channels.daemonStatus(), subscriber(this::onDaemonStatus));
    lcm.subscribe(channels.setpoint(), subscriber(this::onSetpoint));
  }

  private interface Handler {
    void handle(LCMDataInputStream in) throws IOException;
  }

  private LCMSubscriber subscriber(Handler handler) {
    return (LCM source, String channel, LCMDataInputStream in) -> {
      try {
        handler.handle(in);
      } catch (IOException e) {
        undecodable.incrementAndGet();  // a foreign or corrupt message: counted, not thrown
      }
    };
  }

  private void onPlanStatus(LCMDataInputStream in) throws IOException {
    arm_plan_status_t status = new arm_plan_status_t(in);
    MoveHandle move = moves.get(status.request_id);
    MoveState state = MoveState.fromStatus(status.status);
    if (move == null || state == null) return;
    move.update(state, status.reason, status.duration_s);
    if (state.isFinished()) moves.remove(status.request_id);
  }

  private void onDaemonStatus(LCMDataInputStream in) throws IOException {
    arm_daemon_status_t status = new arm_daemon_status_t(in);
    daemonJointNames = List.copyOf(Arrays.asList(status.joint_names));
    daemonStatus = status;
    daemonStatusNanos = System.nanoTime();
  }

  private void onSetpoint(LCMDataInputStream in) throws IOException {
    Consumer<arm_setpoint_t> listener = setpointListener;
    if (listener != null) listener.accept(new arm_setpoint_t(in));
  }

  /**
   * The measured state, 50-200 Hz from the robot's main loop. utime: this machine's time. Dropped
   * without a link (link() says why).
   */
  public void publishState(ArmState measured) {
    if (measured == null) throw new IllegalArgumentException("measured state is null");
    arm_state_t state = new arm_state_t();
    state.utime = System.currentTimeMillis() * 1000;
    int count = measured.count();
    state.num_joints = (byte) count;
    state.position = new double[count];
    state.velocity = new double[count];
    for (int i = 0; i < count; ++i) {
      state.position[i] = measured.position(i);
      state.velocity[i] = measured.velocity(i);
    }
    state.num_pieces = (byte) measured.pieces().size();
    state.pieces = measured.pieces().toArray(new String[0]);
    publish(channels.state(), state);
  }

  /** Publishes if the link is up (trying to bring it up first); false if it is not. */
  private boolean publish(String channel, LCMEncodable message) {
    LCM lcm = link.get();
    if (lcm == null) return false;
    lcm.publish(channel, message);
    return true;
  }

  /**
   * Sends a goal with the next request id. A newer move replaces this one (it ends CANCELLED).
   * Without a link the move ends FAILED at once, with the link's error as its reason. A null pose
   * throws IllegalArgumentException (a Pose checks its own values when it is built).
   */
  public MoveHandle moveTo(Pose pose) {
    if (pose == null) throw new IllegalArgumentException("pose is null");
    MoveHandle move = new MoveHandle(nextRequestId.getAndIncrement(), pose);
    // Moves the daemon never answered (it was gone) are forgotten after MAX_OPEN_MOVES newer ones.
    moves.keySet().removeIf(id -> id <= move.requestId() - MAX_OPEN_MOVES);
    moves.put(move.requestId(), move);
    arm_goal_t goal = new arm_goal_t();
    goal.utime = System.currentTimeMillis() * 1000;
    goal.request_id = move.requestId();
    // A named pose goes as its name, without positions: the daemon resolves it (docs/lcm.md).
    goal.pose_name = pose.poseName();
    goal.num_joints = (byte) pose.positions().size();
    goal.position = new double[goal.num_joints];
    for (int i = 0; i < goal.num_joints; ++i) goal.position[i] = pose.positions().get(i);
    goal.num_pieces = (byte) pose.pieces().size();
    goal.pieces = pose.pieces().toArray(new String[0]);
    goal.scene_name = pose.sceneName();
    goal.scene_offset_m = pose.sceneOffsetM();
    if (!publish(channels.goal(), goal)) {
      moves.remove(move.requestId());
      move.update(MoveState.FAILED, "no LCM link: " + link.lastError(), 0);
    }
    return move;
  }

  /** Asks the daemon to stop a move (ARM_CANCEL); it answers CANCELLED. False without a link. */
  public boolean cancel(MoveHandle move, CancelAction action) {
    return cancel(move.requestId(), action);
  }

  /**
   * Manual override: the daemon stops streaming setpoints for whatever goal is active and reports
   * mode RELEASED until the next goal (docs/roborio.md, "Manual override").
   */
  public boolean release() {
    return cancel(-1, CancelAction.RELEASE);
  }

  private boolean cancel(long requestId, CancelAction action) {
    arm_cancel_t cancel = new arm_cancel_t();
    cancel.utime = System.currentTimeMillis() * 1000;
    cancel.request_id = requestId;
    cancel.action = action.wire();
    return publish(channels.cancel(), cancel);
  }

  /** The LCM link: connected, or why not (docs/roborio.md, "Start-up without a network"). */
  public LcmLink link() {
    return link;
  }

  /** Seconds since the latest ARM_DAEMON_STATUS arrived; +infinity before the first. */
  public double daemonStatusAgeS() {
    return daemonStatus == null ? Double.POSITIVE_INFINITY : (System.nanoTime() - daemonStatusNanos) * 1e-9;
  }

  /** The daemon spoke within maxAgeS (it publishes its status at about 10 Hz). */
  public boolean isDaemonAlive(double maxAgeS) {
    return daemonStatusAgeS() <= maxAgeS;
  }

  /** The daemon's mode from its latest status, or null before the first. */
  public DaemonMode daemonMode() {
    arm_daemon_status_t status = daemonStatus;
    return status == null ? null : DaemonMode.fromWire(status.mode);
  }

  /**
   * The daemon's joints by index with their units, from its latest status, e.g. "pivot rad,
   * telescope m" for a config whose [[joints]] are a pivot then a telescope; "" before any status.
   * ArmController checks the names against its ArmJoints' (daemonJointNames()).
   */
  public String daemonJoints() {
    arm_daemon_status_t status = daemonStatus;
    if (status == null) return "";
    StringBuilder out = new StringBuilder();
    for (int i = 0; i < status.num_joints; ++i) {
      if (i > 0) out.append(", ");
      out.append(status.joint_names[i]).append(' ').append(status.joint_units[i]);
    }
    return out.toString();
  }

  /**
   * The daemon's joints by index, as its config's [[joints]] names them (ARM_DAEMON_STATUS
   * joint_names), e.g. [pivot, telescope]; empty before any status. Unmodifiable.
   */
  public List<String> daemonJointNames() {
    return daemonJointNames;
  }

  /** The latest ARM_DAEMON_STATUS, or null (counters, ages and timings; docs/lcm.md). */
  public arm_daemon_status_t latestDaemonStatus() {
    return daemonStatus;
  }

  /** Messages on our channels that did not decode (e.g. another version of the types). */
  public long undecodableMessages() {
    return undecodable.get();
  }

  /** Called on LCM's thread with every ARM_SETPOINT (desktop simulation: LcmSetpointSource). */
  public void setSetpointListener(Consumer<arm_setpoint_t> listener) {
    setpointListener = listener;
  }

  @Override
  public void close() {
    link.close();
  }
}
