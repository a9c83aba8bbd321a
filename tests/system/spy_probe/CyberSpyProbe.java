// A Java agent for the lcm-spy system test: it rides along in the JVM that tools/lcm-spy starts
// (JAVA_TOOL_OPTIONS=-javaagent:spy_probe.jar=OPTIONS) and reads lcm-spy's channel table, so the
// test sees what a person would see in the window: each channel, the type lcm-spy decoded it as,
// and the message count.
//
// OPTIONS, separated by ';':
//   out=FILE          the table as tab-separated text (header line first), rewritten every 0.5 s
//   expect=C:T,...    channels C that must show type T (lcm-spy decoded them as T) and at least
//                     `min` messages
//   min=N             messages per expected channel (default 3)
//   timeout=SECONDS   give up after this long (default 60)
//   screenshot=FILE   a PNG of the lcm-spy window, taken when done
// When every expected channel is there (or at the timeout) it writes the table one last time,
// takes the screenshot and exits the JVM: status 0 when all were seen, 3 at the timeout.

import java.awt.Component;
import java.awt.Container;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.Window;
import java.io.File;
import java.io.IOException;
import java.lang.reflect.InvocationTargetException;
import java.lang.instrument.Instrumentation;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import javax.imageio.ImageIO;
import javax.swing.JTable;
import javax.swing.SwingUtilities;
import javax.swing.table.TableModel;

public final class CyberSpyProbe {
  private CyberSpyProbe() {}

  public static void premain(String agentArgs, Instrumentation instrumentation) {
    Map<String, String> options = new HashMap<>();
    for (String part : (agentArgs == null ? "" : agentArgs).split(";")) {
      int eq = part.indexOf('=');
      if (eq > 0) options.put(part.substring(0, eq), part.substring(eq + 1));
    }
    Thread thread = new Thread(() -> watch(options), "cyber-spy-probe");
    thread.setDaemon(true);
    thread.start();
  }

  private static void watch(Map<String, String> options) {
    Path out = Path.of(options.getOrDefault("out", "spy_table.tsv"));
    List<String> expect = new ArrayList<>();
    for (String channel : options.getOrDefault("expect", "").split(",")) {
      if (!channel.isEmpty()) expect.add(channel);
    }
    long min = Long.parseLong(options.getOrDefault("min", "3"));
    long deadline = System.nanoTime() + (long) (Double.parseDouble(options.getOrDefault("timeout", "60")) * 1e9);
    boolean seen = false;
    try {
      List<String[]> rows = new ArrayList<>();
      while (!seen && System.nanoTime() < deadline) {
        Thread.sleep(500);
        rows = readTableOr(rows);
        write(out, rows);
        seen = allSeen(rows, expect, min);
      }
      write(out, readTableOr(rows));
      String screenshot = options.get("screenshot");
      if (screenshot != null) screenshot(new File(screenshot));
    } catch (Exception e) {
      System.err.println("cyber-spy-probe: " + e);
      Runtime.getRuntime().halt(4);
    }
    Runtime.getRuntime().halt(seen ? 0 : 3);
  }

  // The table now, or `previous` when it changed while being read: lcm-spy updates its table model
  // from its LCM thread as messages arrive, not only on the event thread, so a row can go between
  // getRowCount and getValueAt. The next read, 0.5 s later, sees it whole.
  private static List<String[]> readTableOr(List<String[]> previous) throws Exception {
    try {
      return readTable();
    } catch (InvocationTargetException e) {
      System.err.println("cyber-spy-probe: the table changed while it was read (" + e.getCause() + "); reading again");
      return previous;
    }
  }

  // Header row first, then one row per channel; empty when no table is up yet.
  private static List<String[]> readTable() throws Exception {
    List<String[]> rows = new ArrayList<>();
    SwingUtilities.invokeAndWait(() -> {
      for (Window window : Window.getWindows()) {
        for (JTable table : tables(window)) {
          TableModel model = table.getModel();
          String[] header = new String[model.getColumnCount()];
          for (int c = 0; c < header.length; ++c) header[c] = model.getColumnName(c);
          rows.add(header);
          for (int r = 0; r < model.getRowCount(); ++r) {
            String[] row = new String[header.length];
            for (int c = 0; c < header.length; ++c) {
              Object value = model.getValueAt(r, c);
              row[c] = value == null ? "" : value.toString();
            }
            rows.add(row);
          }
        }
      }
    });
    return rows;
  }

  private static List<JTable> tables(Component component) {
    List<JTable> found = new ArrayList<>();
    if (component instanceof JTable) found.add((JTable) component);
    if (component instanceof Container) {
      for (Component child : ((Container) component).getComponents()) found.addAll(tables(child));
    }
    return found;
  }

  private static boolean allSeen(List<String[]> rows, List<String> expect, long min) {
    if (rows.isEmpty()) return false;
    List<String> header = Arrays.asList(rows.get(0));
    int channel = header.indexOf("Channel");
    int type = header.indexOf("Type");
    int count = header.indexOf("Num Msgs");
    if (channel < 0 || type < 0 || count < 0) return false;
    for (String wanted : expect) {
      String[] channelAndType = wanted.split(":", 2);
      if (channelAndType.length != 2) return false;
      boolean ok = false;
      for (String[] row : rows.subList(1, rows.size())) {
        if (row[channel].equals(channelAndType[0]) && row[type].equals(channelAndType[1])
            && parseCount(row[count]) >= min) {
          ok = true;
        }
      }
      if (!ok) return false;
    }
    return true;
  }

  private static long parseCount(String text) {
    try {
      return Long.parseLong(text.trim());
    } catch (NumberFormatException e) {
      return -1;
    }
  }

  private static void write(Path out, List<String[]> rows) throws IOException {
    StringBuilder text = new StringBuilder();
    for (String[] row : rows) text.append(String.join("\t", row)).append('\n');
    Path tmp = out.resolveSibling(out.getFileName() + ".tmp");
    Files.writeString(tmp, text.toString(), StandardCharsets.UTF_8);
    Files.move(tmp, out, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
  }

  private static void screenshot(File file) throws Exception {
    Rectangle bounds = null;
    for (Window window : Window.getWindows()) {
      if (window.isShowing()) {
        bounds = bounds == null ? window.getBounds() : bounds.union(window.getBounds());
      }
    }
    if (bounds == null) return;
    ImageIO.write(new Robot().createScreenCapture(bounds), "png", file);
  }
}
