package cyberplanner.roborio.sim;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.LongSupplier;

/**
 * Whether the daemon stopped for a stale ARM_STATE during an attempt. It then rightly stops and
 * holds where the latest state said the mechanism was (docs/roborio.md), and the move proves
 * nothing either way: on a busy machine either this JVM's loop was starved (a gap between two
 * publications longer than state_timeout_s, measured here) or the daemon's own loop, which
 * stamps ARM_STATE at receipt, was (the daemon logs the stop; this reads its log). Thread-safe:
 * the publishing loop ticks, the test reads.
 */
final class StarvationWatch {
  /**
   * Attempts of one action at the most. On the 2-core machine at load 12-18 with a core kept busy
   * the daemon stopped for a stale state in about 1 of 10 attempts, often two in a row (its loop
   * at normal priority): a third is what keeps the suite green there, and a real error still fails
   * in every attempt that was not starved.
   */
  static final int MAX_ATTEMPTS = 3;

  private final double stateTimeoutS;
  private final LongSupplier clockNanos;
  private final LongSupplier daemonStaleStops;
  private long lastTickNanos;
  private long largestGapNanos;
  private long largestGapEverNanos;
  private int voided;

  /**
   * @param stateTimeoutS the daemon's state_timeout_s, from the config the daemon runs with
   * @param daemonStaleStops how many times the daemon said so far that it stopped for a stale ARM_STATE
   */
  StarvationWatch(double stateTimeoutS, LongSupplier clockNanos, LongSupplier daemonStaleStops) {
    this.stateTimeoutS = stateTimeoutS;
    this.clockNanos = clockNanos;
    this.daemonStaleStops = daemonStaleStops;
  }

  /**
   * From what tests/integration/roborio_integration_test.sh passes in: the config's
   * state_timeout_s (cyber.state_timeout_s) and the daemon's log (cyber.daemon_log).
   */
  static StarvationWatch fromDaemon() {
    String timeout = System.getProperty("cyber.state_timeout_s");
    String log = System.getProperty("cyber.daemon_log");
    if (timeout == null || log == null) {
      throw new IllegalStateException("no -Dcyber.state_timeout_s or -Dcyber.daemon_log "
          + "(tests/integration/roborio_integration_test.sh passes them)");
    }
    return new StarvationWatch(Double.parseDouble(timeout), System::nanoTime, () -> staleStopsIn(Path.of(log)));
  }

  /** The daemon's log line of such a stop: daemon/core/src/motion_gate.cpp, at warning level. */
  static long staleStopsIn(Path log) {
    try {
      return Files.readAllLines(log, StandardCharsets.UTF_8).stream()
          .filter(line -> line.contains("motion stopped") && line.contains("ARM_STATE is stale"))
          .count();
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    }
  }

  double stateTimeoutS() {
    return stateTimeoutS;
  }

  long daemonStaleStops() {
    return daemonStaleStops.getAsLong();
  }

  /** Called by the loop right after it published ARM_STATE. */
  synchronized void tick() {
    long now = clockNanos.getAsLong();
    if (lastTickNanos != 0) {
      largestGapNanos = Math.max(largestGapNanos, now - lastTickNanos);
      largestGapEverNanos = Math.max(largestGapEverNanos, largestGapNanos);
    }
    lastTickNanos = now;
  }

  /** An action whose checks mean something only if the daemon's state stayed fresh. */
  interface Attempt {
    /** Does the action (attempt 1, 2, ...) and returns its checks, run only if it was not starved. */
    Runnable run(int attempt) throws Exception;
  }

  /** What puts the world back where the void attempt started, before the next. */
  interface Restore {
    void run() throws Exception;
  }

  /**
   * Runs the attempt; when the daemon's state went stale meanwhile, says why, restores and runs it
   * again instead of checking it. Starved MAX_ATTEMPTS times in a row fails: the checks of a move
   * are never skipped altogether.
   */
  void checkUnlessStarved(String what, Attempt attempt, Restore restore) throws Exception {
    for (int i = 1; ; ++i) {
      long gapNanos;
      synchronized (this) {
        largestGapNanos = 0;
      }
      long stopsBefore = daemonStaleStops.getAsLong();
      Runnable checks = attempt.run(i);
      synchronized (this) {  // a silence still going on counts too
        long silenceNanos = lastTickNanos == 0 ? Long.MAX_VALUE : clockNanos.getAsLong() - lastTickNanos;
        gapNanos = Math.max(largestGapNanos, silenceNanos);
      }
      long stops = daemonStaleStops.getAsLong() - stopsBefore;
      // As the daemon judges it (daemon/core/src/motion_gate.cpp): stale when older than the timeout, not at it.
      boolean jvmStarved = gapNanos > Math.round(stateTimeoutS * 1e9);
      if (!jvmStarved && stops == 0) {
        checks.run();
        return;
      }
      String why = String.format("%s: void: the daemon logged %d stops for a stale ARM_STATE, this JVM's loop "
          + "published it with gaps up to %.3f s (state_timeout_s %.3f s)%s", what, stops, gapNanos * 1e-9,
          stateTimeoutS, jvmStarved ? ": this JVM was starved" : "");
      synchronized (this) {
        ++voided;
      }
      if (i == MAX_ATTEMPTS) throw new AssertionError(why + ", in all " + MAX_ATTEMPTS + " attempts");
      System.out.println("starved: " + why + "; once more");
      restore.run();
    }
  }

  /** How many attempts were void. */
  synchronized int voided() {
    return voided;
  }

  /** The largest gap between two ticks so far, s. */
  synchronized double largestGapS() {
    return largestGapEverNanos * 1e-9;
  }
}
