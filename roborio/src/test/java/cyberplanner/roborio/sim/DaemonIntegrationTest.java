package cyberplanner.roborio.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import cyberplanner.arm_plan_status_t;
import cyberplanner.arm_setpoint_t;
import cyberplanner.roborio.ArmController;
import cyberplanner.roborio.ArmJoint;
import cyberplanner.roborio.ArmState;
import cyberplanner.roborio.Channels;
import cyberplanner.roborio.CyberPlannerClient;
import cyberplanner.roborio.HoldFallback;
import cyberplanner.roborio.JointChain;
import cyberplanner.roborio.JointGravity;
import cyberplanner.roborio.LcmSetpointSource;
import cyberplanner.roborio.MoveHandle;
import cyberplanner.roborio.MoveState;
import cyberplanner.roborio.Pose;
import cyberplanner.roborio.SetpointGuard;
import cyberplanner.roborio.can.DaemonMode;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import lcm.lcm.LCM;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;

/**
 * The Java side against the real cyber-plannerd (--can none, setpoint_echo_full_rate = true), in
 * the network namespace tests/integration/roborio_integration_test.sh sets up. Tagged "daemon":
 * the unit run excludes it. Poses: tests/support/public_moves.cpp (the reference robot's), none of
 * the "no path" ones (coral L4, algae HOLD_HIGH; docs/performance.md).
 */
@Tag("daemon")
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class DaemonIntegrationTest {
  static final String URL = System.getProperty("cyber.lcm.url", "udpm://239.255.76.67:5810?ttl=0");
  static final double LOOP_S = 0.005;  // the robot loop of the simulation, 200 Hz
  // The reference robot's joint 0 is an elevator (m), joint 1 an arm (rad).
  static final JointChain REFERENCE_JOINTS = JointChain.of("elevator", "arm");
  static final double JOINT0_TOLERANCE_M = 0.002;
  static final double JOINT1_TOLERANCE_RAD = 0.005;
  // On the hold setpoints, in a row: SimulatedMechanism's critically damped joints (30 rad/s) leave
  // (1 + 9) e^-9 = 0.12 % of the error they started the settling with.
  static final double SETTLE_S = 0.3;
  static final double SETTLE_WITHIN_S = 10.0;
  // Speeds (m/s and rad/s together) below this are a mechanism at rest.
  static final double STILL = 1e-3;
  // How much the time to a goal after an interruption varies between two runs of the same
  // interruption: the daemon splices a goal one planning budget ahead, which follows its latest
  // planning times (docs/operations.md, "What it does"). Measured on the 2-core machine under
  // load: up to 15 ms.
  static final double HANDOVER_SPREAD_S = 0.025;
  /**
   * How far into STOW -> L4 (about 0.8 s) the second goal comes: early, so that on a loaded machine
   * (the echo that tells the test how far the move is arrives late) the first move is still going
   * when the second is planned. At 0.3 s, at load 17, the first had finished in one run of four.
   */
  static final double INTERRUPT_AT_S = 0.15;

  /**
   * The robot side of the simulated mechanism, always enabled, talking to the daemon through client:
   * its joints named as the reference config names them (the guard checks them against the daemon's).
   */
  static ArmController armOn(CyberPlannerClient client, SimulatedMechanism mechanism, SetpointGuard guard) {
    List<ArmJoint> joints = List.of(ArmJoint.of("elevator", mechanism.joints.get(0), JointGravity.NONE),
        ArmJoint.of("arm", mechanism.joints.get(1), JointGravity.NONE));
    return new ArmController(new ArmController.Parts(client, new LcmSetpointSource(client), joints,
        mechanism::state, () -> true, () -> System.nanoTime() / 1000), guard, new HoldFallback(joints));
  }

  static SetpointGuard guard() {
    return new SetpointGuard(REFERENCE_JOINTS, 0.05, 0.25);
  }

  static void awaitDaemon(CyberPlannerClient client) throws InterruptedException {
    for (int i = 0; i < 1200 && !client.isDaemonAlive(0.5); ++i) Thread.sleep(50);  // grids at start-up
    assertTrue(client.isDaemonAlive(0.5), "no ARM_DAEMON_STATUS within 60 s");
  }

  @Test
  @Order(1)
  void aJavaClientGetsAMoveDoneWithSetpointsOnArmSetpoint() throws Exception {
    try (CyberPlannerClient client = new CyberPlannerClient(new LCM(URL), Channels.DEFAULT, 5000)) {
      List<arm_setpoint_t> setpoints = new CopyOnWriteArrayList<>();
      client.setSetpointListener(setpoints::add);
      awaitDaemon(client);
      assertEquals("elevator m, arm rad", client.daemonJoints());  // the config's [[joints]], by index
      StarvationWatch watch = StarvationWatch.fromDaemon();
      Thread publisher = new Thread(() -> {
        while (!Thread.currentThread().isInterrupted()) {
          client.publishState(ArmState.of(0.58, 0.0, 2.97, 0.0));  // at rest at INTAKE
          watch.tick();
          try {
            Thread.sleep(10);
          } catch (InterruptedException e) {
            return;
          }
        }
      });
      publisher.start();
      try {
        for (int i = 0; i < 100 && client.daemonMode() != DaemonMode.HOLDING; ++i) Thread.sleep(50);
        assertEquals(DaemonMode.HOLDING, client.daemonMode());
        // A stale ARM_STATE cancels the move or makes the daemon hold INTAKE again (the state says so):
        // nothing to restore.
        watch.checkUnlessStarved("client: INTAKE -> L3", attempt -> {
          // By name: the daemon resolves [poses.none] L3 = [1.22, 5.69] with its config (docs/lcm.md).
          MoveHandle move = client.moveTo(Pose.named("L3"));  // INTAKE -> L3
          MoveState end = move.await(30);
          System.out.println("client: " + move + ", trajectory " + move.durationS() + " s");
          long moving = setpoints.stream()
              .filter(s -> s.request_id == move.requestId() && s.mode == arm_setpoint_t.MODE_MOVING).count();
          // The echo of the last tick may come after DONE (one loop in the daemon sends both): the hold.
          arm_setpoint_t hold = null;
          for (int i = 0; i < 200 && hold == null && end == MoveState.DONE; ++i) {
            hold = setpoints.stream()
                .filter(s -> s.request_id == move.requestId() && s.mode == arm_setpoint_t.MODE_HOLDING)
                .findFirst().orElse(null);
            if (hold == null) Thread.sleep(10);
          }
          arm_setpoint_t last = hold;
          System.out.println("client: " + moving + " ARM_SETPOINT messages while moving");
          return () -> {
            assertEquals(MoveState.DONE, end, move.toString());
            assertTrue(move.durationS() > 0);
            // Full-rate echo: about one per 5 ms stream period over the trajectory.
            assertTrue(moving >= 0.5 * move.durationS() / 0.005, moving + " moving setpoints");
            assertTrue(last != null, "no ARM_SETPOINT holding request " + move.requestId() + " within 2 s of DONE");
            assertEquals(1.22, last.position[0], 1e-5);
            assertEquals(5.69, last.position[1], 1e-5);
          };
        }, () -> {});
        System.out.printf("client: void attempts %d, largest ARM_STATE gap %.3f s%n", watch.voided(),
            watch.largestGapS());
      } finally {
        publisher.interrupt();
        publisher.join();
      }
    }
  }

  @Test
  @Order(2)
  void aSimulatedRobotFollowsASequenceOfMovesWithAndWithoutGamePieces() throws Exception {
    // From L3, where the client's move left the daemon holding.
    List<Pose> sequence = List.of(
        Pose.of(0.20, 1.57),                 // none: L3 -> STOW
        Pose.of(0.58, 2.97),                 // none: STOW -> INTAKE
        Pose.of(0.78, 6.09).holding("coral"),  // coral: INTAKE -> L2
        Pose.of(1.27, 5.79).holding("coral"),  // coral: L2 -> L3
        Pose.of(0.20, 1.57).holding("coral"),  // coral: L3 -> STOW
        Pose.of(1.93, 1.71).holding("algae"),  // algae: STOW -> NET
        Pose.of(0.20, 1.57).holding("algae"),  // algae: NET -> STOW
        Pose.of(1.97, 5.17));                // none: STOW -> L4
    SimulatedMechanism mechanism = new SimulatedMechanism(1.22, 5.69);
    try (CyberPlannerClient client = new CyberPlannerClient(new LCM(URL), Channels.DEFAULT, 6000)) {
      awaitDaemon(client);
      SetpointGuard guard = guard();
      ArmController subsystem = armOn(client, mechanism, guard);
      StarvationWatch watch = StarvationWatch.fromDaemon();
      RobotLoop loop = new RobotLoop(subsystem, mechanism, watch);
      watch.checkUnlessStarved("sim: start", attempt -> {
        loop.runFor(1.0);  // the daemon takes the state and holds it
        SetpointGuard.Verdict verdict = subsystem.verdict();
        return () -> assertEquals(SetpointGuard.Verdict.USE, verdict);
      }, () -> {});
      for (Pose goal : sequence) {
        mechanism.setPieces(goal.pieces());
        // A stale ARM_STATE stops the move, or the hold at its end, where the state lagged behind.
        ArmState from = mechanism.state();
        watch.checkUnlessStarved("sim: " + goal, attempt -> {
          MoveHandle command = subsystem.moveTo(goal);
          double waited = 0;
          while (!command.isFinished() && waited < 30) {
            loop.runFor(LOOP_S);
            waited += LOOP_S;
          }
          long fallbackBefore = loop.fallbackLoops;
          boolean settled = loop.settle(SETTLE_S, SETTLE_WITHIN_S);
          ArmState at = mechanism.state();
          double joint0Error = Math.abs(at.position(0) - goal.position(0));
          double joint1Error = Math.abs(at.position(1) - goal.position(1));
          System.out.printf("sim: %s done in %.3f s planned, error %.2e m %.2e rad, verdict %s, loops outside USE %d%n",
              goal, command.durationS(), joint0Error, joint1Error, subsystem.verdict(),
              loop.fallbackLoops - fallbackBefore);
          return () -> {
            assertTrue(command.isDone(), goal + ": " + command);
            assertTrue(settled, goal + ": not " + SETTLE_S + " s in a row on the setpoints in " + SETTLE_WITHIN_S
                + " s");
            assertTrue(command.durationS() > 0.1, goal + ": no real move");  // restart() put it back
            assertTrue(joint0Error <= JOINT0_TOLERANCE_M, goal + ": joint 0 error " + joint0Error);
            assertTrue(joint1Error <= JOINT1_TOLERANCE_RAD, goal + ": joint 1 error " + joint1Error);
          };
        }, () -> restart(loop, mechanism, from, watch));
      }
      System.out.printf("sim: %d moves, lost setpoints joint 0 %d joint 1 %d, loops outside USE %d of %d, "
          + "void attempts %d, largest ARM_STATE gap %.3f s%n", sequence.size(), guard.lostFrames("elevator"),
          guard.lostFrames("arm"), loop.fallbackLoops, loop.loops, watch.voided(), watch.largestGapS());
    }
  }

  @Test
  @Order(3)
  void aMoveCancelledMidwayEndsCancelledAndTheDaemonHolds() throws Exception {
    // ARM_CANCEL with ACTION_HOLD (docs/lcm.md): the daemon brakes to rest and holds there.
    SimulatedMechanism mechanism = new SimulatedMechanism(1.97, 5.17);  // where order 2 left it (L4)
    try (CyberPlannerClient client = new CyberPlannerClient(new LCM(URL), Channels.DEFAULT, 7000)) {
      awaitDaemon(client);
      ArmController arm = armOn(client, mechanism, guard());
      StarvationWatch watch = StarvationWatch.fromDaemon();
      RobotLoop loop = new RobotLoop(arm, mechanism, watch);
      loop.runFor(1.0);
      ArmState from = mechanism.state();
      watch.checkUnlessStarved("cancel: L4 -> STOW", attempt -> {
        MoveHandle move = arm.moveTo(Pose.of(0.20, 1.57));
        for (int i = 0; i < 2000 && move.state() != MoveState.EXECUTING && !move.isFinished(); ++i) loop.runFor(LOOP_S);
        loop.runFor(0.2);  // well into the move
        MoveState before = move.state();
        arm.cancel(move);
        for (int i = 0; i < 400 && !move.isFinished(); ++i) loop.runFor(LOOP_S);
        boolean settled = loop.settle(SETTLE_S, SETTLE_WITHIN_S);
        // The daemon holds once its stop (or, when no stop could be spliced in time, the running
        // motion) has ended: a slow daemon (a sanitizer build) reports HOLDING later, not never.
        for (int i = 0; i < 1000 && client.daemonMode() != DaemonMode.HOLDING; ++i) loop.runFor(LOOP_S);
        DaemonMode mode = client.daemonMode();
        return () -> {
          assertEquals(MoveState.EXECUTING, before, move.toString());
          assertEquals(MoveState.CANCELLED, move.state(), move.toString());
          assertTrue(settled, "no hold after the cancel");
          assertEquals(DaemonMode.HOLDING, mode);
        };
      }, () -> restart(loop, mechanism, from, watch));
    }
  }

  /** How a move handed over to the next goal, from the robot's interruption of it. */
  record Handover(MoveHandle first, MoveHandle second, double finishS, int cancels, List<arm_setpoint_t> between,
      double slowestMeasured) {
    String describe(String how) {
      return String.format("%s: %s, %s, at the goal %.3f s after the interruption, %d cancels, %d setpoints "
          + "before the goal's first, measured speed at least %.3f", how, first, second, finishS, cancels,
          between.size(), slowestMeasured);
    }
  }

  /**
   * The daemon's note that it planned requestId from where the running motion ends, its planning
   * budget outlasting that motion (daemon/core/src/goal_coordinator.cpp): {ends in, budget} in
   * seconds, or null when it spliced the goal in.
   */
  static double[] plannedFromTheEnd(long requestId) throws IOException {
    Pattern note = Pattern.compile("request " + requestId + ": the running motion ends in ([0-9.]+) ms, within the "
        + "planning budget of ([0-9.]+) ms; planning from where it ends");
    Path log = Path.of(System.getProperty("cyber.daemon_log"));
    for (String line : Files.readAllLines(log, StandardCharsets.UTF_8)) {
      Matcher m = note.matcher(line);
      if (m.find()) return new double[] {Double.parseDouble(m.group(1)) * 1e-3, Double.parseDouble(m.group(2)) * 1e-3};
    }
    return null;
  }

  /**
   * From rest at start, moves to first and, trajectoryS into that move (the daemon's echo says how
   * far it is), interrupts it for second: handedOver, as MoveToPoseCommand's end(true) and its
   * successor's initialize() do it; otherwise with a cancel (HOLD) at once and the goal right after.
   */
  static Handover interruptForAnotherGoal(ArmController arm, RobotLoop loop, LcmRecorder recorder, Pose start,
      Pose first, double trajectoryS, Pose second, boolean handedOver) throws InterruptedException {
    MoveHandle toStart = arm.moveTo(start);
    for (int i = 0; i < 6000 && !toStart.isFinished(); ++i) loop.runFor(LOOP_S);
    loop.settle(SETTLE_S, SETTLE_WITHIN_S);
    MoveHandle toFirst = arm.moveTo(first);
    for (int i = 0; i < 2000 && !toFirst.isFinished(); ++i) {
      if (recorder.trajectoryTimeS(toFirst.requestId()) >= trajectoryS) break;
      loop.runFor(LOOP_S);
    }
    recorder.clear();
    long interruptedMicros = LcmRecorder.wallMicros();
    if (handedOver) {
      arm.cancelUnlessReplaced(toFirst);
    } else {
      arm.cancel(toFirst);
    }
    MoveHandle toSecond = arm.moveTo(second);
    double slowest = Double.POSITIVE_INFINITY;
    for (int i = 0; i < 6000 && !toSecond.isFinished(); ++i) {
      loop.runFor(LOOP_S);
      if (recorder.firstSetpointOf(toSecond.requestId()) == null) slowest = Math.min(slowest, loop.mechanism.speed());
    }
    loop.settle(SETTLE_S, SETTLE_WITHIN_S);
    long doneMicros = recorder.statusMicros(toSecond.requestId(), arm_plan_status_t.STATUS_DONE);
    return new Handover(toFirst, toSecond, (doneMicros - interruptedMicros) * 1e-6, recorder.cancels.size(),
        recorder.setpointsBefore(toSecond.requestId()), slowest);
  }

  @Test
  @Order(4)
  void aMoveInterruptedByAGoalKeepsMovingAndIsNeverSlowerThanBrakingFirst() throws Exception {
    // A driver asks for L3 while the elevator and arm are on their way from STOW to L4.
    Pose stow = Pose.of(0.20, 1.57);
    Pose l4 = Pose.of(1.97, 5.17);
    Pose l3 = Pose.of(1.22, 5.69);
    SimulatedMechanism mechanism = new SimulatedMechanism(0.20, 1.57);
    try (LcmRecorder recorder = new LcmRecorder(URL);
        CyberPlannerClient client = new CyberPlannerClient(new LCM(URL), Channels.DEFAULT, 8000)) {
      awaitDaemon(client);
      ArmController arm = armOn(client, mechanism, guard());
      StarvationWatch watch = StarvationWatch.fromDaemon();
      RobotLoop loop = new RobotLoop(arm, mechanism, watch);
      loop.runFor(0.5);  // the daemon takes the state (or still holds where order 3 left it: start goes there)
      watch.checkUnlessStarved("handover: STOW -> L4, L3 " + INTERRUPT_AT_S + " s into it", attempt -> {
        double interruptAtS = INTERRUPT_AT_S;
        Handover braked = interruptForAnotherGoal(arm, loop, recorder, stow, l4, interruptAtS, l3, false);
        Handover handed = interruptForAnotherGoal(arm, loop, recorder, stow, l4, interruptAtS, l3, true);
        // A slow daemon (a sanitizer build's: 0.45 s for STOW -> L4) splices one planning budget
        // ahead, 1.25 times its slowest recent plan (docs/operations.md, "What it does"): past the
        // end of the first move, it rightly plans the second from where the first ends, or the
        // first's superseded status has not come yet. That proves nothing either way: both runs are
        // repeated, interrupted earlier; a daemon that never supersedes still fails below.
        for (int again = 1; again < StarvationWatch.MAX_ATTEMPTS
            && (handed.first().state() == MoveState.DONE || !handed.first().reason().startsWith("superseded"));
            ++again) {
          interruptAtS /= 2;
          System.out.println("handover: the first move ended before the second was planned; once more, " + interruptAtS
              + " s into it");
          braked = interruptForAnotherGoal(arm, loop, recorder, stow, l4, interruptAtS, l3, false);
          handed = interruptForAnotherGoal(arm, loop, recorder, stow, l4, interruptAtS, l3, true);
        }
        Handover brakedFirst = braked;
        Handover handedOver = handed;
        System.out.println("handover: " + brakedFirst.describe("cancel at once") + "; " + handedOver.describe("handed over"));
        double[] notSpliced = plannedFromTheEnd(handedOver.second().requestId());
        return () -> {
          assertEquals(1, brakedFirst.cancels(), "the recorder sees ARM_CANCEL");
          assertEquals(MoveState.DONE, handedOver.second().state(), handedOver.second().toString());
          if (handedOver.first().state() == MoveState.DONE && notSpliced != null) {
            // Interrupted early, and still the daemon plans slower than the rest of the move (a
            // sanitizer build's under load: up to 0.67 s): nothing to hand over, and it says why.
            System.out.printf("handover: not checked: the daemon's budget %.3f s outlasts the %.3f s left%n",
                notSpliced[1], notSpliced[0]);
            assertTrue(notSpliced[1] > notSpliced[0], "the daemon's own numbers");
            return;
          }
          assertEquals("superseded by request " + handedOver.second().requestId(), handedOver.first().reason());
          assertEquals(0, handedOver.cancels(), "ARM_CANCEL between the two moves");
          assertFalse(handedOver.between().isEmpty());
          for (arm_setpoint_t s : handedOver.between()) {
            assertEquals(arm_setpoint_t.MODE_MOVING, s.mode, "setpoint mode before the second move's");
            assertTrue(Math.hypot(s.velocity[0], s.velocity[1]) > STILL, "commanded to rest before the second move");
          }
          assertTrue(handedOver.slowestMeasured() > STILL, "measured at rest before the second move");
          assertTrue(handedOver.finishS() <= brakedFirst.finishS() + HANDOVER_SPREAD_S, "handed over " + handedOver.finishS()
              + " s, braking first " + brakedFirst.finishS() + " s");
        };
      }, () -> restart(loop, mechanism, ArmState.of(0.20, 0, 1.57, 0), watch));
    }
  }

  /**
   * Puts the mechanism back where a void attempt started (it may have coasted anywhere on the last
   * setpoint, even past a joint limit, and the daemon holds there) and makes the daemon take that
   * state as it takes any after a stop: silence past state_timeout_s, until it logs the stop, then
   * the loop again, as at the start.
   */
  static void restart(RobotLoop loop, SimulatedMechanism mechanism, ArmState from, StarvationWatch watch)
      throws InterruptedException {
    long stops = watch.daemonStaleStops();
    Thread.sleep(Math.round(watch.stateTimeoutS() * 1e3));
    for (int i = 0; i < 100 && watch.daemonStaleStops() == stops; ++i) Thread.sleep(50);
    mechanism.placeAt(from);
    loop.resume();
    loop.runFor(1.0);
  }

  /** The robot's main loop at 200 Hz in real time: subsystem.periodic(), then the model. */
  static final class RobotLoop {
    final ArmController subsystem;
    final SimulatedMechanism mechanism;
    final StarvationWatch watch;
    long next = System.nanoTime();
    long loops;
    long fallbackLoops;

    RobotLoop(ArmController subsystem, SimulatedMechanism mechanism, StarvationWatch watch) {
      this.subsystem = subsystem;
      this.mechanism = mechanism;
      this.watch = watch;
    }

    /**
     * Runs until the mechanism followed the setpoints (verdict USE) for seconds in a row, at most
     * withinS; true if it did. After a stall the loop catches up faster than the setpoints arrive,
     * and the guard holds the mechanism where it was meanwhile (HoldFallback): that is no settling.
     */
    boolean settle(double seconds, double withinS) throws InterruptedException {
      long needed = Math.round(seconds / LOOP_S);
      long inRow = 0;
      for (long i = 0; inRow < needed && i < Math.round(withinS / LOOP_S); ++i) {
        runFor(LOOP_S);
        inRow = subsystem.verdict() == SetpointGuard.Verdict.USE ? inRow + 1 : 0;
      }
      return inRow >= needed;
    }

    /** Goes on after a pause without catching up on the periods missed. */
    void resume() {
      next = System.nanoTime();
    }

    void runFor(double seconds) throws InterruptedException {
      for (int i = 0; i < Math.round(seconds / LOOP_S); ++i) {
        subsystem.periodic();  // publishes ARM_STATE first
        watch.tick();
        if (subsystem.verdict() != SetpointGuard.Verdict.USE) fallbackLoops++;
        loops++;
        mechanism.step(LOOP_S);
        next += (long) (LOOP_S * 1e9);
        long sleep = next - System.nanoTime();
        if (sleep > 0) Thread.sleep(sleep / 1_000_000, (int) (sleep % 1_000_000));
      }
    }
  }
}
