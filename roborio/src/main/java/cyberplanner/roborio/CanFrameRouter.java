package cyberplanner.roborio;

import cyberplanner.roborio.can.CanFrame;
import cyberplanner.roborio.can.Coded;
import cyberplanner.roborio.can.DaemonStatus;
import cyberplanner.roborio.can.FrcCanId;
import cyberplanner.roborio.can.Setpoint;
import cyberplanner.roborio.can.SetpointFrame;
import cyberplanner.roborio.can.StatusFrame;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;

/**
 * Hands every frame of cyber-plannerd read off a CAN bus to the guard, in order, with the time it
 * was received (the layers' CAN stream sources read them; docs/can-protocol.md): one setpoint
 * stream per joint, each on the device number the daemon's config gives that joint. The devices
 * are the config's [daemon.devices] table, keyed by the joints' names and "status" (of), or the
 * daemon's numbering without the table (defaults): 1 to N in joint order, N + 1 for the status.
 * The joints come from the guard (their names, by index), so one table serves any chain its keys
 * name. A frame that does not decode, or that is of another device, is counted and ignored.
 */
public final class CanFrameRouter {
  /** The 29-bit id and mask that select all of our frames (device type 10, manufacturer 8). */
  public static final int STREAM_ID = FrcCanId.teamFrameId(0, 0);
  public static final int STREAM_MASK = 0x1FFF0000;
  /** The key of the status frame's device in [daemon.devices]. */
  public static final String STATUS_KEY = "status";
  /** The largest device number the daemon's config takes (docs/configuration.md). */
  public static final int MAX_CONFIG_DEVICE = 62;

  /** The config's table (sorted by key, for messages), or null for the daemon's default numbering. */
  private final Map<String, Integer> devices;
  private JointChain resolvedFor;
  private final int[] jointOfDevice = new int[FrcCanId.MAX_DEVICE_NUMBER + 1];
  private int statusDevice;
  private long undecodable;
  private long foreign;

  private CanFrameRouter(Map<String, Integer> devices) {
    this.devices = devices;
  }

  /**
   * The daemon's [daemon.devices] table: the device number of each joint's setpoint frames, by the
   * joint's [[joints]] name, and of the status frame, by "status"; e.g. {@code Map.of("elevator", 1,
   * "arm", 2, "status", 3)}. Numbers 0 to 62, no number twice, a "status" key
   * (IllegalArgumentException otherwise). Whether every joint has a key, and every key is a joint's
   * or "status", is checked against the arm's joints (checkJoints, ArmController).
   */
  public static CanFrameRouter of(Map<String, Integer> devices) {
    if (devices == null) throw new IllegalArgumentException("devices is null");
    Map<String, Integer> table = new TreeMap<>();
    Set<Integer> numbers = new HashSet<>();
    for (Map.Entry<String, Integer> entry : devices.entrySet()) {
      String key = entry.getKey();
      Integer number = entry.getValue();
      if (key == null || number == null) {
        throw new IllegalArgumentException("a device key or number is null: " + devices);
      }
      if (number < 0 || number > MAX_CONFIG_DEVICE) {
        throw new IllegalArgumentException("device " + key + " = " + number + " is outside 0.." + MAX_CONFIG_DEVICE);
      }
      if (!numbers.add(number)) {
        throw new IllegalArgumentException("device number " + number + " is used twice in " + devices);
      }
      table.put(key, number);
    }
    if (!table.containsKey(STATUS_KEY)) throw new IllegalArgumentException("no \"status\" device in " + devices);
    return new CanFrameRouter(table);
  }

  /** The daemon's numbering without a [daemon.devices] table: joints 1 to N in chain order, status N + 1. */
  public static CanFrameRouter defaults() {
    return new CanFrameRouter(null);
  }

  /**
   * Throws IllegalArgumentException, naming the joints, unless every joint has a device and every
   * key is a joint's or "status".
   */
  public void checkJoints(JointChain joints) {
    resolve(joints);
  }

  /** The device number of each joint's setpoint frames, by index. */
  public int[] jointDevices(JointChain joints) {
    resolve(joints);
    int[] out = new int[joints.count()];
    for (int device = 0; device < jointOfDevice.length; ++device) {
      if (jointOfDevice[device] >= 0) out[jointOfDevice[device]] = device;
    }
    return out;
  }

  /** The status frame's device number (for the defaults it depends on the joint count). */
  public int statusDevice(JointChain joints) {
    resolve(joints);
    return statusDevice;
  }

  private void resolve(JointChain joints) {
    if (joints == resolvedFor || joints.equals(resolvedFor)) return;
    int[] table = new int[jointOfDevice.length];
    Arrays.fill(table, -1);
    int status;
    if (devices == null) {
      for (int i = 0; i < joints.count(); ++i) table[i + 1] = i;
      status = joints.count() + 1;
    } else {
      // As the daemon's loader: every joint has a key, and every key is a joint's or "status".
      List<String> missing = new ArrayList<>();
      for (int i = 0; i < joints.count(); ++i) {
        Integer number = devices.get(joints.name(i));
        if (number == null) missing.add(joints.name(i));
        else table[number] = i;
      }
      if (!missing.isEmpty()) {
        throw new IllegalArgumentException("the devices " + devices + " have no key for joint"
            + (missing.size() == 1 ? " " : "s ") + String.join(", ", missing) + " (the joints: " + joints + ")");
      }
      for (String key : devices.keySet()) {
        if (!key.equals(STATUS_KEY) && !joints.names().contains(key)) {
          throw new IllegalArgumentException("device key \"" + key + "\" is neither a joint's name (" + joints
              + ") nor \"status\"");
        }
      }
      status = devices.get(STATUS_KEY);
    }
    System.arraycopy(table, 0, jointOfDevice, 0, table.length);
    statusDevice = status;
    resolvedFor = joints;
  }

  /**
   * One extended data frame: its 29-bit id, data[0..length), received at receivedMicros; a
   * setpoint goes to the guard as the setpoint of the joint whose device sent it.
   */
  public void offer(SetpointGuard guard, int id, byte[] data, int length, long receivedMicros) {
    resolve(guard.joints());
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
    int joint = jointOfDevice[device];
    if (joint < 0 || FrcCanId.teamFrameId(FrcCanId.SETPOINT_API_ID, device) != frame.id()) {
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
