package cyberplanner.roborio;

/** What the robot does while cyber-planner setpoints must not be used (ArmController). */
public interface Fallback {
  /** Called every enabled loop while the verdict is not USE. */
  void run(SetpointGuard.Verdict why, ArmState measured);

  /**
   * Called every loop in which the fallback does not run (setpoints used, robot disabled, manual
   * override): the next run() starts afresh from the mechanism as it is then.
   */
  default void reset() {}
}
