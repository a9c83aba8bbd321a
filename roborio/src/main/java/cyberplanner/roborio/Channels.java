package cyberplanner.roborio;

/** LCM channel names; the defaults are the daemon's ([daemon.channels], docs/configuration.md). */
public record Channels(String goal, String state, String planStatus, String setpoint, String daemonStatus,
    String cancel) {
  public static final Channels DEFAULT =
      new Channels("ARM_GOAL", "ARM_STATE", "ARM_PLAN_STATUS", "ARM_SETPOINT", "ARM_DAEMON_STATUS", "ARM_CANCEL");
}
