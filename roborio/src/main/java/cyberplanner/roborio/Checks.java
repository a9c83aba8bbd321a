package cyberplanner.roborio;

import cyberplanner.arm_goal_t;
import java.util.ArrayList;
import java.util.List;

/**
 * The checks a Pose and an ArmState make when they are built, so a mistake throws
 * IllegalArgumentException in the robot program's own call rather than reaching the daemon as a
 * message it rejects (or LCM's Java encoder mangling it).
 */
final class Checks {
  /** Pieces a goal or a state can name (arm_goal_t.MAX_PIECES, the same as arm_state_t's). */
  static final int MAX_PIECES = arm_goal_t.MAX_PIECES;
  /** Joints a goal can carry (arm_goal_t.MAX_JOINTS; the daemon takes its robot's count only). */
  static final int MAX_JOINTS = arm_goal_t.MAX_JOINTS;

  private Checks() {}

  static double finite(String what, double value) {
    if (!Double.isFinite(value)) throw new IllegalArgumentException(what + " is " + value + ", not a finite number");
    return value;
  }

  /** An unmodifiable copy of positions: at most MAX_JOINTS values, each finite. */
  static List<Double> positions(List<Double> positions) {
    if (positions == null) throw new IllegalArgumentException("positions is null");
    if (positions.size() > MAX_JOINTS) {
      throw new IllegalArgumentException(positions.size() + " positions " + positions + ": at most " + MAX_JOINTS);
    }
    for (int i = 0; i < positions.size(); ++i) {
      Double value = positions.get(i);
      if (value == null) throw new IllegalArgumentException("joint " + i + " position is null");
      finite("joint " + i + " position", value);
    }
    return List.copyOf(positions);
  }

  /**
   * An unmodifiable copy of pieces: at most MAX_PIECES names, each non-empty printable ASCII (a
   * config's [pieces.NAME] key; LCM's Java encoder writes one byte per char, so anything else would
   * arrive as another name).
   */
  static List<String> pieces(List<String> pieces) {
    if (pieces == null) throw new IllegalArgumentException("pieces is null (use no pieces for none)");
    if (pieces.size() > MAX_PIECES) {
      throw new IllegalArgumentException(pieces.size() + " pieces " + pieces + ": at most " + MAX_PIECES);
    }
    List<String> copy = new ArrayList<>(pieces.size());
    for (String name : pieces) {
      if ("".equals(name)) throw new IllegalArgumentException("a piece name is empty");
      copy.add(ascii("piece name", name));
    }
    return List.copyOf(copy);
  }

  /** A name for the daemon (a piece, a scene): non-null, printable ASCII. */
  static String ascii(String what, String name) {
    if (name == null) throw new IllegalArgumentException(what + " is null");
    for (int i = 0; i < name.length(); ++i) {
      char c = name.charAt(i);
      if (c < 0x20 || c > 0x7E) throw new IllegalArgumentException(what + " \"" + name + "\" is not printable ASCII");
    }
    return name;
  }
}
