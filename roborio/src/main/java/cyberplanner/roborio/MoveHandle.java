package cyberplanner.roborio;

/**
 * One move sent to cyber-plannerd: its request id and what the daemon last said about it. Updated
 * by the client's LCM thread, read from anywhere.
 */
public final class MoveHandle {
  private final long requestId;
  private final Pose goal;
  private MoveState state = MoveState.SENT;
  private String reason = "";
  private double durationS;

  MoveHandle(long requestId, Pose goal) {
    this.requestId = requestId;
    this.goal = goal;
  }

  public long requestId() {
    return requestId;
  }

  public Pose goal() {
    return goal;
  }

  public synchronized MoveState state() {
    return state;
  }

  /** The daemon's reason: always set for REJECTED, FAILED and CANCELLED; may be empty otherwise. */
  public synchronized String reason() {
    return reason;
  }

  /** Duration of the planned trajectory, s (0 before a plan). */
  public synchronized double durationS() {
    return durationS;
  }

  public synchronized boolean isFinished() {
    return state.isFinished();
  }

  public synchronized boolean isDone() {
    return state == MoveState.DONE;
  }

  /** Waits until the move is finished or timeoutS passed; returns the state then. */
  public synchronized MoveState await(double timeoutS) throws InterruptedException {
    long deadline = System.nanoTime() + (long) (timeoutS * 1e9);
    while (!state.isFinished()) {
      long left = deadline - System.nanoTime();
      if (left <= 0) break;
      wait(Math.max(1, left / 1_000_000));
    }
    return state;
  }

  /** A status message about this move. A finished move never changes again. */
  synchronized void update(MoveState next, String why, double duration) {
    if (state.isFinished()) return;
    state = next;
    reason = why == null ? "" : why;
    if (duration > 0) durationS = duration;
    notifyAll();
  }

  @Override
  public synchronized String toString() {
    return "request " + requestId + " " + state.name().toLowerCase() + (reason.isEmpty() ? "" : ": " + reason);
  }
}
