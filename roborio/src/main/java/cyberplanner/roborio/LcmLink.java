package cyberplanner.roborio;

import java.io.IOException;
import java.util.function.Consumer;
import java.util.function.LongSupplier;
import lcm.lcm.LCM;

/**
 * The client's LCM connection, opened lazily: `new LCM("udpm://...")` throws (SocketException "No
 * such device") while the host has no route for the multicast group (USB-tethered, before DHCP,
 * static address without gateway). The robot program must start anyway, so the link tries again,
 * at most once per retry interval, whenever the client is used, and says why it is not up
 * (docs/roborio.md, "Start-up without a network"). Thread-safe.
 */
public final class LcmLink {
  /** Opens the LCM instance, e.g. `() -> new LCM(url)`. */
  public interface Opener {
    LCM open() throws IOException;
  }

  private final Opener opener;
  private final long retryNanos;
  private final LongSupplier clockNanos;
  private final Consumer<LCM> onOpen;
  private volatile LCM lcm;
  private volatile String lastError = "not tried yet";
  private volatile long failedAttempts;
  private long nextTryNanos;
  private boolean closed;

  /** onOpen runs once, right after the open succeeded (the client subscribes there). */
  public LcmLink(Opener opener, double retryS, LongSupplier clockNanos, Consumer<LCM> onOpen) {
    this.opener = opener;
    this.retryNanos = Math.round(retryS * 1e9);
    this.clockNanos = clockNanos;
    this.onOpen = onOpen;
  }

  /** The open LCM, trying to open it if the retry interval passed; null while there is none. */
  public synchronized LCM get() {
    if (lcm != null || closed) return lcm;
    long now = clockNanos.getAsLong();
    if (failedAttempts > 0 && now - nextTryNanos < 0) return null;
    try {
      LCM opened = opener.open();
      onOpen.accept(opened);
      lcm = opened;
      lastError = "";
    } catch (IOException e) {
      failedAttempts++;
      lastError = e.getClass().getSimpleName() + ": " + e.getMessage();
      nextTryNanos = now + retryNanos;
    }
    return lcm;
  }

  public boolean isConnected() {
    return lcm != null;
  }

  /** Why the link is not up ("" once it is): the exception of the latest attempt. */
  public String lastError() {
    return lastError;
  }

  /** Attempts that failed so far. */
  public long failedAttempts() {
    return failedAttempts;
  }

  public synchronized void close() {
    closed = true;
    if (lcm != null) lcm.close();
  }
}
