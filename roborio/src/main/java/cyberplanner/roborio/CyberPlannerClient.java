package cyberplanner.roborio;

import cyberplanner.arm_daemon_status_t;
import cyberplanner.arm_goal_t;
import cyberplanner.arm_plan_status_t;
import cyberplanner.arm_setpoint_t;
import cyberplanner.arm_state_t;
import cyberplanner.roborio.can.DaemonMode;
import java.io.IOException;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import lcm.lcm.LCM;
import lcm.lcm.LCMDataInputStream;
import lcm.lcm.LCMSubscriber;

/**
 * The robot's side of cyber-plannerd's LCM interface (docs/lcm.md): publishes ARM_STATE, sends
 * goals with a request id each and tracks their ARM_PLAN_STATUS, and watches ARM_DAEMON_STATUS
 * for the daemon's liveness and mode. Ages are measured with this machine's monotonic clock at
 * receipt (the daemon's utime is another machine's clock). Thread-safe; LCM delivers on its own
 * thread.
 */
public final class CyberPlannerClient implements AutoCloseable {
  /** The robot LAN: the URL of the installed /etc/cyber-planner/robot.toml (docs/roborio.md). */
  public static final String ROBOT_LAN_URL = "udpm://239.255.76.67:7667?ttl=1";

  private static final long MAX_OPEN_MOVES = 1000;

  private final LCM lcm;
  private final Channels channels;
  private final AtomicLong nextRequestId;
  private final Map<Long, MoveHandle> moves = new ConcurrentHashMap<>();
  private volatile arm_daemon_status_t daemonStatus;
  private volatile long daemonStatusNanos;
  private volatile Consumer<arm_setpoint_t> setpointListener;
  private final AtomicLong undecodable = new AtomicLong();

  /** Opens LCM at url; request ids start at 1. */
  public CyberPlannerClient(String url) throws IOException {
    this(new LCM(url), Channels.DEFAULT, 1);
  }

  /**
   * @param firstRequestId the first move's request id; the next ones count up (a robot program
   *     that restarts may start from, e.g., the time, so old answers are not taken for new moves)
   */
  public CyberPlannerClient(LCM lcm, Channels channels, long firstRequestId) {
    this.lcm = lcm;
    this.channels = channels;
    this.nextRequestId = new AtomicLong(firstRequestId);
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
    daemonStatus = new arm_daemon_status_t(in);
    daemonStatusNanos = System.nanoTime();
  }

  private void onSetpoint(LCMDataInputStream in) throws IOException {
    Consumer<arm_setpoint_t> listener = setpointListener;
    if (listener != null) listener.accept(new arm_setpoint_t(in));
  }

  /** The measured state, 50-200 Hz from the robot's main loop. utime: this machine's time. */
  public void publishState(double elevatorM, double elevatorMps, double armRad, double armRadps, boolean heldCoral,
      boolean heldAlgae) {
    arm_state_t state = new arm_state_t();
    state.utime = System.currentTimeMillis() * 1000;
    state.elevator_m = elevatorM;
    state.elevator_mps = elevatorMps;
    state.arm_rad = armRad;
    state.arm_radps = armRadps;
    state.held_coral = heldCoral;
    state.held_algae = heldAlgae;
    lcm.publish(channels.state(), state);
  }

  /** Sends a goal with the next request id. A newer move replaces this one (it ends CANCELLED). */
  public MoveHandle moveTo(Pose pose) {
    MoveHandle move = new MoveHandle(nextRequestId.getAndIncrement(), pose);
    // Moves the daemon never answered (it was gone) are forgotten after MAX_OPEN_MOVES newer ones.
    moves.keySet().removeIf(id -> id <= move.requestId() - MAX_OPEN_MOVES);
    moves.put(move.requestId(), move);
    arm_goal_t goal = new arm_goal_t();
    goal.utime = System.currentTimeMillis() * 1000;
    goal.request_id = move.requestId();
    goal.elevator_m = pose.elevatorM();
    goal.arm_rad = pose.armRad();
    goal.held_coral = pose.heldCoral();
    goal.held_algae = pose.heldAlgae();
    goal.scene_name = pose.sceneName();
    lcm.publish(channels.goal(), goal);
    return move;
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
    lcm.close();
  }
}
