package cyberplanner.roborio.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The void rule of DaemonIntegrationTest, on a clock the test moves: checks are skipped only for
 * an attempt in which the loop was silent longer than the timeout, that attempt is repeated once,
 * and a check that fails in an attempt that was not starved fails.
 */
class StarvationWatchTest {
  static final double TIMEOUT_S = 0.25;
  static final long LOOP_NANOS = 5_000_000;

  final long[] nowNanos = {1_000_000_000L};
  final StarvationWatch watch = new StarvationWatch(TIMEOUT_S, () -> nowNanos[0]);

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
    });
    assertEquals(List.of(1), checked);
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
    }));
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
    });
    assertEquals(List.of(2), checked);
    assertEquals(1, watch.voided());
    assertEquals(TIMEOUT_S, watch.largestGapS(), 1e-8);
  }

  @Test
  void starvedTwiceFails() {
    loop(1, LOOP_NANOS);
    AssertionError error = assertThrows(AssertionError.class, () -> watch.checkUnlessStarved("starved twice",
        attempt -> {
          loop(2, (long) (2 * TIMEOUT_S * 1e9));
          return () -> {};
        }));
    assertTrue(error.getMessage().contains("second attempt"), error.getMessage());
    assertEquals(2, watch.voided());
  }

  @Test
  void aSilenceStillGoingOnCounts() {
    loop(1, LOOP_NANOS);
    assertThrows(AssertionError.class, () -> watch.checkUnlessStarved("silent", attempt -> {
      nowNanos[0] += (long) (TIMEOUT_S * 1e9) + 1;  // no tick: the publisher stopped
      return () -> {};
    }));
  }

  @Test
  void aLoopThatNeverPublishedIsStarved() {
    assertThrows(AssertionError.class, () -> watch.checkUnlessStarved("never", attempt -> () -> {}));
  }
}
