package cyberplanner.roborio.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The void rule of DaemonIntegrationTest, on a clock and a daemon log the test writes: checks are
 * skipped only for an attempt in which the loop was silent longer than the timeout or the daemon
 * logged a stop for a stale state, the world is restored and the attempt repeated once, and a
 * check that fails in an attempt that was not starved fails.
 */
class StarvationWatchTest {
  static final double TIMEOUT_S = 0.25;
  static final long LOOP_NANOS = 5_000_000;

  final long[] nowNanos = {1_000_000_000L};
  final long[] daemonStops = {0};
  final StarvationWatch watch = new StarvationWatch(TIMEOUT_S, () -> nowNanos[0], () -> daemonStops[0]);
  int restored;

  /** The loop publishes n times, every gapNanos. */
  void loop(int n, long gapNanos) {
    for (int i = 0; i < n; ++i) {
      nowNanos[0] += gapNanos;
      watch.tick();
    }
  }

  @Test
  void anAttemptTheLoopKeptFreshIsCheckedOnce() throws Exception {
    loop(1, LOOP_NANOS);
    List<Integer> checked = new ArrayList<>();
    watch.checkUnlessStarved("fresh", attempt -> {
      loop(100, (long) (TIMEOUT_S * 1e9));  // the limit itself is still fresh, as in the daemon
      return () -> checked.add(attempt);
    }, () -> ++restored);
    assertEquals(List.of(1), checked);
    assertEquals(0, restored);
    assertEquals(0, watch.voided());
  }

  @Test
  void aFailingCheckOfAFreshAttemptFails() {
    loop(1, LOOP_NANOS);
    assertThrows(AssertionError.class, () -> watch.checkUnlessStarved("fresh", attempt -> {
      loop(10, LOOP_NANOS);
      return () -> {
        throw new AssertionError("position error");
      };
    }, () -> ++restored));
  }

  @Test
  void aStarvedAttemptIsVoidAndTheSecondIsChecked() throws Exception {
    loop(1, LOOP_NANOS);
    List<Integer> checked = new ArrayList<>();
    watch.checkUnlessStarved("starved once", attempt -> {
      loop(10, LOOP_NANOS);
      if (attempt == 1) {
        loop(1, (long) (TIMEOUT_S * 1e9) + 1);
        loop(10, LOOP_NANOS);
        return () -> {
          throw new AssertionError("the void attempt's checks must not run");
        };
      }
      return () -> checked.add(attempt);
    }, () -> ++restored);
    assertEquals(List.of(2), checked);
    assertEquals(1, watch.voided());
    assertEquals(1, restored);
    assertEquals(TIMEOUT_S, watch.largestGapS(), 1e-8);
  }

  @Test
  void starvedInEveryAttemptFails() {
    loop(1, LOOP_NANOS);
    AssertionError error = assertThrows(AssertionError.class, () -> watch.checkUnlessStarved("starved always",
        attempt -> {
          loop(2, (long) (2 * TIMEOUT_S * 1e9));
          return () -> {};
        }, () -> ++restored));
    assertTrue(error.getMessage().contains("in all " + StarvationWatch.MAX_ATTEMPTS), error.getMessage());
    assertEquals(StarvationWatch.MAX_ATTEMPTS, watch.voided());
    assertEquals(StarvationWatch.MAX_ATTEMPTS - 1, restored);
  }

  @Test
  void aSilenceStillGoingOnCounts() {
    loop(1, LOOP_NANOS);
    assertThrows(AssertionError.class, () -> watch.checkUnlessStarved("silent", attempt -> {
      nowNanos[0] += (long) (TIMEOUT_S * 1e9) + 1;  // no tick: the publisher stopped
      return () -> {};
    }, () -> ++restored));
  }

  @Test
  void aLoopThatNeverPublishedIsStarved() {
    assertThrows(AssertionError.class, () -> watch.checkUnlessStarved("never", attempt -> () -> {}, () -> ++restored));
  }

  @Test
  void aStopTheDaemonLoggedMakesTheAttemptVoidThoughThisLoopWasFresh() throws Exception {
    loop(1, LOOP_NANOS);
    List<Integer> checked = new ArrayList<>();
    watch.checkUnlessStarved("daemon starved", attempt -> {
      loop(10, LOOP_NANOS);
      if (attempt == 1) daemonStops[0] += 2;
      return () -> checked.add(attempt);
    }, () -> {
      ++restored;
      daemonStops[0] += 1;  // the restore's own stop is not the second attempt's
    });
    assertEquals(List.of(2), checked);
    assertEquals(1, restored);
  }

  @Test
  void theDaemonsLogLineIsCounted(@TempDir Path dir) throws IOException {
    Path log = dir.resolve("daemon.log");
    Files.writeString(log, "2026-12-01 23:47:07.695 info request 6000 done\n"
        + "2026-12-01 23:47:07.949 warning motion stopped: ARM_STATE is stale\n"
        + "2026-12-01 23:47:07.968 info holding elevator 0.1704 m, arm 1.4804 rad (motion allowed)\n"
        + "2026-12-01 23:47:08.368 warning motion stopped: ARM_STATE is stale\n");
    assertEquals(2, StarvationWatch.staleStopsIn(log));
  }
}
