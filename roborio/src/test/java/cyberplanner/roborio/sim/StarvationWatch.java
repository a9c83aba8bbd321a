package cyberplanner.roborio.sim;

import java.util.function.LongSupplier;

/**
 * The largest gap between two ARM_STATE publications of a loop, in real time. A gap longer than
 * the daemon's state_timeout_s makes the daemon stop and hold where the latest state said the
 * mechanism was (docs/roborio.md): on a busy machine that is the JVM starved, not an error of the
 * daemon or the library, and the move it happened in proves nothing either way. Thread-safe: the
 * publishing loop ticks, the test reads.
 */
final class StarvationWatch {
  private final double stateTimeoutS;
  private final LongSupplier clockNanos;
  private long lastTickNanos;
  private long largestGapNanos;
  private long largestGapEverNanos;
  private int voided;

  /** stateTimeoutS: the daemon's state_timeout_s, from the config the daemon runs with. */
  StarvationWatch(double stateTimeoutS, LongSupplier clockNanos) {
    this.stateTimeoutS = stateTimeoutS;
    this.clockNanos = clockNanos;
  }

  /** The state_timeout_s the script passes in (system property cyber.state_timeout_s). */
  static StarvationWatch fromDaemonConfig() {
    String value = System.getProperty("cyber.state_timeout_s");
    if (value == null) {
      throw new IllegalStateException("no -Dcyber.state_timeout_s (tests/integration/roborio_integration_test.sh "
          + "reads it from the daemon's config)");
    }
    return new StarvationWatch(Double.parseDouble(value), System::nanoTime);
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

  /** An action whose checks mean something only if the loop kept the daemon's state fresh. */
  interface Attempt {
    /** Does the action (attempt 1 or 2) and returns its checks, run only if it was not starved. */
    Runnable run(int attempt) throws Exception;
  }

  /**
   * Runs the attempt; when the loop went silent longer than state_timeout_s meanwhile, says so
   * and runs it once more instead of checking it. Starved twice in a row fails: the checks of a
   * move are never skipped altogether.
   */
  void checkUnlessStarved(String what, Attempt attempt) throws Exception {
    for (int i = 1; ; ++i) {
      long gapNanos;
      synchronized (this) {
        largestGapNanos = 0;
      }
      Runnable checks = attempt.run(i);
      synchronized (this) {  // a silence still going on counts too
        long silenceNanos = lastTickNanos == 0 ? Long.MAX_VALUE : clockNanos.getAsLong() - lastTickNanos;
        gapNanos = Math.max(largestGapNanos, silenceNanos);
      }
      // As the daemon judges it (daemon/core/src/motion_gate.cpp): stale when older than the timeout, not at it.
      if (gapNanos <= Math.round(stateTimeoutS * 1e9)) {
        checks.run();
        return;
      }
      String why = String.format("%s: void: the loop publishing ARM_STATE was silent for %.3f s, longer than the "
          + "daemon's state_timeout_s %.3f s (the daemon rightly stopped)", what, gapNanos * 1e-9, stateTimeoutS);
      synchronized (this) {
        ++voided;
      }
      if (i == 2) throw new AssertionError(why + ", in the second attempt too");
      System.out.println("starved: " + why + "; once more");
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
