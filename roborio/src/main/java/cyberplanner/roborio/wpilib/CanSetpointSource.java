package cyberplanner.roborio.wpilib;

import cyberplanner.roborio.Joint;
import cyberplanner.roborio.SetpointGuard;
import cyberplanner.roborio.SetpointSource;
import cyberplanner.roborio.can.CanFrame;
import cyberplanner.roborio.can.Coded;
import cyberplanner.roborio.can.DaemonStatus;
import cyberplanner.roborio.can.FrcCanId;
import cyberplanner.roborio.can.Setpoint;
import cyberplanner.roborio.can.SetpointFrame;
import cyberplanner.roborio.can.StatusFrame;
import edu.wpi.first.hal.CANData;
import edu.wpi.first.wpilibj.CAN;

/**
 * Reads the setpoint and status frames off the roboRIO's CAN bus with WPILib's CAN class
 * (docs/can-protocol.md, "Reading the frames on the roboRIO"). Device numbers are those of the
 * daemon's [daemon.devices] section. A frame that does not decode is counted and ignored.
 */
public final class CanSetpointSource implements SetpointSource {
  private final CAN elevator;
  private final CAN arm;
  private final CAN daemon;
  private final int elevatorDevice;
  private final int armDevice;
  private final int statusDevice;
  private final CANData packet = new CANData();
  private long undecodable;

  public CanSetpointSource(int elevatorDevice, int armDevice, int statusDevice) {
    this.elevatorDevice = elevatorDevice;
    this.armDevice = armDevice;
    this.statusDevice = statusDevice;
    elevator = new CAN(elevatorDevice, FrcCanId.MANUFACTURER_TEAM_USE, FrcCanId.DEVICE_TYPE_MISCELLANEOUS);
    arm = new CAN(armDevice, FrcCanId.MANUFACTURER_TEAM_USE, FrcCanId.DEVICE_TYPE_MISCELLANEOUS);
    daemon = new CAN(statusDevice, FrcCanId.MANUFACTURER_TEAM_USE, FrcCanId.DEVICE_TYPE_MISCELLANEOUS);
  }

  /** The reference configuration's devices: elevator 1, arm 2, status 3. */
  public static CanSetpointSource withReferenceDevices() {
    return new CanSetpointSource(1, 2, 3);
  }

  @Override
  public void poll(SetpointGuard guard, long nowMicros) {
    // readPacketNew: only a packet not seen before, so a repeat is not taken for a fresh setpoint.
    if (elevator.readPacketNew(FrcCanId.SETPOINT_API_ID, packet)) {
      offerSetpoint(guard, Joint.ELEVATOR, elevatorDevice, nowMicros);
    }
    if (arm.readPacketNew(FrcCanId.SETPOINT_API_ID, packet)) offerSetpoint(guard, Joint.ARM, armDevice, nowMicros);
    if (daemon.readPacketNew(FrcCanId.STATUS_API_ID, packet)) {
      Coded<DaemonStatus> status = StatusFrame.decode(frameOf(FrcCanId.STATUS_API_ID, statusDevice));
      if (status.ok()) {
        guard.onStatus(status.value().mode(), nowMicros);
      } else {
        undecodable++;
      }
    }
  }

  private void offerSetpoint(SetpointGuard guard, Joint joint, int device, long nowMicros) {
    Coded<Setpoint> setpoint = SetpointFrame.decode(frameOf(FrcCanId.SETPOINT_API_ID, device));
    if (setpoint.ok()) {
      guard.onSetpoint(joint, setpoint.value(), nowMicros);
    } else {
      undecodable++;
    }
  }

  // WPILib's CAN class matches the id for us; the decoder still checks the length.
  private CanFrame frameOf(int apiId, int device) {
    return CanFrame.extendedData(FrcCanId.teamFrameId(apiId, device), packet.data, Math.min(packet.length, 8));
  }

  /** Frames read that did not decode (wrong length, undefined mode). */
  public long undecodableFrames() {
    return undecodable;
  }
}
