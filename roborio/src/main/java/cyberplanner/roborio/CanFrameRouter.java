package cyberplanner.roborio;

import cyberplanner.roborio.can.CanFrame;
import cyberplanner.roborio.can.Coded;
import cyberplanner.roborio.can.DaemonStatus;
import cyberplanner.roborio.can.FrcCanId;
import cyberplanner.roborio.can.Setpoint;
import cyberplanner.roborio.can.SetpointFrame;
import cyberplanner.roborio.can.StatusFrame;

/**
 * Hands every frame of cyber-plannerd read off a CAN bus to the guard, in order, with the time it
 * was received (the layers' CAN stream sources read them; docs/can-protocol.md). Device numbers
 * are those of the daemon's [daemon.devices]. A frame that does not decode, or that is of another
 * device, is counted and ignored.
 */
public final class CanFrameRouter {
  /** The 29-bit id and mask that select all of our frames (device type 10, manufacturer 8). */
  public static final int STREAM_ID = FrcCanId.teamFrameId(0, 0);
  public static final int STREAM_MASK = 0x1FFF0000;

  private final int joint0Device;
  private final int joint1Device;
  private final int statusDevice;
  private long undecodable;
  private long foreign;

  /** The device numbers of joint 0's and joint 1's setpoint frames and of the status frame. */
  public CanFrameRouter(int joint0Device, int joint1Device, int statusDevice) {
    this.joint0Device = joint0Device;
    this.joint1Device = joint1Device;
    this.statusDevice = statusDevice;
  }

  /** The shipped configurations' devices: joint 0 on 1, joint 1 on 2, status 3. */
  public static CanFrameRouter reference() {
    return new CanFrameRouter(1, 2, 3);
  }

  /** One extended data frame: its 29-bit id, data[0..length), received at receivedMicros. */
  public void offer(SetpointGuard guard, int id, byte[] data, int length, long receivedMicros) {
    CanFrame frame = CanFrame.extendedData(id & 0x1FFFFFFF, data, Math.min(Math.max(length, 0), data.length));
    int device = id & 0x3F;
    if (FrcCanId.teamFrameId(FrcCanId.STATUS_API_ID, device) == frame.id()) {
      if (device != statusDevice) {
        foreign++;
        return;
      }
      Coded<DaemonStatus> status = StatusFrame.decode(frame);
      if (status.ok()) guard.onStatus(status.value().mode(), receivedMicros);
      else undecodable++;
      return;
    }
    Joint joint = device == joint0Device ? Joint.JOINT_0 : device == joint1Device ? Joint.JOINT_1 : null;
    if (joint == null || FrcCanId.teamFrameId(FrcCanId.SETPOINT_API_ID, device) != frame.id()) {
      foreign++;
      return;
    }
    Coded<Setpoint> setpoint = SetpointFrame.decode(frame);
    if (setpoint.ok()) guard.onSetpoint(joint, setpoint.value(), receivedMicros);
    else undecodable++;
  }

  /** Frames of ours that did not decode (wrong length, undefined mode). */
  public long undecodableFrames() {
    return undecodable;
  }

  /** Frames of the team-use range that are not the configured devices' (another team use). */
  public long foreignFrames() {
    return foreign;
  }
}
