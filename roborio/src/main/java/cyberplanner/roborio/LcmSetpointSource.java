package cyberplanner.roborio;

import cyberplanner.arm_setpoint_t;
import cyberplanner.roborio.can.DaemonMode;
import cyberplanner.roborio.can.Setpoint;
import java.util.concurrent.atomic.AtomicReference;

/**
 * Desktop simulation: the setpoints from ARM_SETPOINT instead of CAN, for robot code and
 * `cyber-plannerd --can none` on one machine. The daemon must publish every stream tick
 * (`setpoint_echo_full_rate = true`, docs/configuration.md); the message's mode stands in for the
 * status frame. Device numbers are not on LCM: the setpoints carry device -1.
 */
public final class LcmSetpointSource implements SetpointSource {
  private final AtomicReference<arm_setpoint_t> latest = new AtomicReference<>();
  private arm_setpoint_t applied;

  public LcmSetpointSource(CyberPlannerClient client) {
    client.setSetpointListener(latest::set);
  }

  @Override
  public void poll(SetpointGuard guard, long nowMicros) {
    arm_setpoint_t message = latest.get();
    if (message == null || message == applied) return;
    applied = message;
    DaemonMode mode = DaemonMode.fromWire(message.mode);
    if (mode == null) return;
    guard.onStatus(mode, nowMicros);
    guard.onSetpoint(Joint.ELEVATOR, new Setpoint(-1, message.elevator_m, message.elevator_mps, message.elevator_volts,
        message.elevator_sequence & 0xFF), nowMicros);
    guard.onSetpoint(Joint.ARM, new Setpoint(-1, message.arm_rad, message.arm_radps, message.arm_volts,
        message.arm_sequence & 0xFF), nowMicros);
  }
}
