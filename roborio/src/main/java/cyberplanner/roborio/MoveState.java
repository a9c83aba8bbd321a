package cyberplanner.roborio;

/** The life of one move (ARM_PLAN_STATUS, docs/lcm.md), plus SENT before the daemon answers. */
public enum MoveState {
  SENT(false),
  ACCEPTED(false),
  PLANNING(false),
  EXECUTING(false),
  DONE(true),
  REJECTED(true),
  FAILED(true),
  CANCELLED(true);

  private final boolean finished;

  MoveState(boolean finished) {
    this.finished = finished;
  }

  /** DONE, REJECTED, FAILED or CANCELLED: the daemon sends nothing more about this move. */
  public boolean isFinished() {
    return finished;
  }

  /** The state of an arm_plan_status_t STATUS_* value, or null for an unknown one. */
  public static MoveState fromStatus(int status) {
    return switch (status) {
      case cyberplanner.arm_plan_status_t.STATUS_ACCEPTED -> ACCEPTED;
      case cyberplanner.arm_plan_status_t.STATUS_PLANNING -> PLANNING;
      case cyberplanner.arm_plan_status_t.STATUS_EXECUTING -> EXECUTING;
      case cyberplanner.arm_plan_status_t.STATUS_DONE -> DONE;
      case cyberplanner.arm_plan_status_t.STATUS_REJECTED -> REJECTED;
      case cyberplanner.arm_plan_status_t.STATUS_FAILED -> FAILED;
      case cyberplanner.arm_plan_status_t.STATUS_CANCELLED -> CANCELLED;
      default -> null;
    };
  }
}
