package cyberplanner.roborio.can;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.Consumer;
import org.junit.jupiter.api.Test;

/**
 * tests/vectors/can_frames.txt against the Java decoder and encoder: the same file the C++ codec's
 * test reads (tests/unit/can/can_shared_vectors_test.cpp). The file's header gives the format.
 */
class SharedVectorsTest {
  record Line(int number, String kind, List<String> inputs, List<String> expected) {
    String where() {
      return "tests/vectors/can_frames.txt:" + number;
    }
  }

  static List<Line> lines(String kind) throws IOException {
    Path file = Path.of(System.getProperty("cyber.source.dir", "."), "tests/vectors/can_frames.txt");
    List<String> text = Files.readAllLines(file);
    List<Line> out = new ArrayList<>();
    for (int i = 0; i < text.size(); ++i) {
      String line = text.get(i).trim();
      if (line.isEmpty() || line.startsWith("#")) continue;
      List<String> tokens = Arrays.asList(line.split("\\s+"));
      int arrow = tokens.indexOf("->");
      if (!tokens.get(0).equals(kind)) continue;
      out.add(new Line(i + 1, kind, tokens.subList(1, arrow), tokens.subList(arrow + 1, tokens.size())));
    }
    assertTrue(out.size() >= 3, "too few " + kind + " vectors");
    return out;
  }

  /** candump's frame syntax (see the file's header). */
  static CanFrame parseFrame(String text) {
    int hash = text.indexOf('#');
    String id = text.substring(0, hash);
    String rest = text.substring(hash + 1);
    int value = Integer.parseUnsignedInt(id, 16);
    boolean extended = id.length() == 8;
    boolean error = extended && (value & 0x20000000) != 0;
    if (error) return new CanFrame(value & 0x1FFFFFFF, false, false, true, hexBytes(rest));
    if (rest.startsWith("R")) return new CanFrame(value, extended, true, false, new byte[0]);
    return new CanFrame(value, extended, false, false, hexBytes(rest));
  }

  static byte[] hexBytes(String hex) {
    byte[] out = new byte[hex.length() / 2];
    for (int i = 0; i < out.length; ++i) out[i] = (byte) Integer.parseInt(hex.substring(2 * i, 2 * i + 2), 16);
    return out;
  }

  static String formatFrame(CanFrame frame) {
    StringBuilder out = new StringBuilder(String.format("%08X#", frame.id()));
    for (byte b : frame.data()) out.append(String.format("%02X", b & 0xFF));
    return out.toString();
  }

  static CodecError errorNamed(String name) {
    return CodecError.valueOf(name.toUpperCase().replace('-', '_'));
  }

  static <T> void expect(Coded<T> result, Line line, Consumer<T> check) {
    if (line.expected().get(0).equals("error")) {
      assertFalse(result.ok(), line.where() + ": expected " + line.expected().get(1));
      assertEquals(errorNamed(line.expected().get(1)), result.error(), line.where());
    } else {
      assertTrue(result.ok(), line.where() + ": " + result.error());
      check.accept(result.value());
    }
  }

  static int integer(String text) {
    return Integer.parseInt(text);
  }

  @Test
  void decodeSetpoint() throws IOException {
    for (Line line : lines("decode-setpoint")) {
      expect(SetpointFrame.decode(parseFrame(line.inputs().get(0))), line, setpoint -> {
        List<String> e = line.expected();
        assertEquals(integer(e.get(0)), setpoint.device(), line.where());
        assertEquals(integer(e.get(1)) / SetpointFrame.POSITION_COUNTS_PER_UNIT, setpoint.position(), 0.0, line.where());
        assertEquals(integer(e.get(2)) / SetpointFrame.VELOCITY_COUNTS_PER_UNIT, setpoint.velocity(), 0.0, line.where());
        assertEquals(integer(e.get(3)) / SetpointFrame.VOLTAGE_COUNTS_PER_VOLT, setpoint.feedforwardVolts(), 0.0,
            line.where());
        assertEquals(integer(e.get(4)), setpoint.sequence(), line.where());
      });
    }
  }

  @Test
  void encodeSetpoint() throws IOException {
    for (Line line : lines("encode-setpoint")) {
      List<String> in = line.inputs();
      Setpoint setpoint = new Setpoint(integer(in.get(0)), Double.parseDouble(in.get(1)), Double.parseDouble(in.get(2)),
          Double.parseDouble(in.get(3)), integer(in.get(4)));
      expect(SetpointFrame.encode(setpoint), line,
          frame -> assertEquals(line.expected().get(0), formatFrame(frame), line.where()));
    }
  }

  @Test
  void decodeStatus() throws IOException {
    for (Line line : lines("decode-status")) {
      expect(StatusFrame.decode(parseFrame(line.inputs().get(0))), line, status -> {
        List<String> e = line.expected();
        assertEquals(integer(e.get(0)), status.device(), line.where());
        assertEquals(integer(e.get(1)), status.mode().wire(), line.where());
        assertEquals(integer(e.get(2)), status.requestIdLow16(), line.where());
        assertEquals(integer(e.get(3)), status.timeRemainingMs(), line.where());
        assertEquals(integer(e.get(4)), status.faultBits(), line.where());
        assertEquals(integer(e.get(5)), status.sequence(), line.where());
      });
    }
  }

  @Test
  void encodeStatus() throws IOException {
    for (Line line : lines("encode-status")) {
      List<String> in = line.inputs();
      DaemonStatus status = new DaemonStatus(integer(in.get(0)), DaemonMode.fromWire(integer(in.get(1))),
          integer(in.get(2)), integer(in.get(3)), integer(in.get(4)), integer(in.get(5)));
      expect(StatusFrame.encode(status), line,
          frame -> assertEquals(line.expected().get(0), formatFrame(frame), line.where()));
    }
  }

  @Test
  void requestIdLow16() throws IOException {
    for (Line line : lines("request-low16")) {
      assertEquals(integer(line.expected().get(0)), StatusFrame.requestIdLow16(Long.parseLong(line.inputs().get(0))),
          line.where());
    }
  }

  @Test
  void everyErrorIsExpectedSomewhere() throws IOException {
    List<String> all = Files.readAllLines(Path.of(System.getProperty("cyber.source.dir", "."), "tests/vectors/can_frames.txt"));
    for (CodecError error : CodecError.values()) {
      String name = "error " + error.name().toLowerCase().replace('_', '-');
      assertTrue(all.stream().anyMatch(l -> !l.startsWith("#") && l.endsWith(name)), "no vector expects " + name);
    }
  }
}
