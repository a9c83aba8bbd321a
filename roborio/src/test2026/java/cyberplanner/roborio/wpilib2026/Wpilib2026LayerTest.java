package cyberplanner.roborio.wpilib2026;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.ctre.phoenix6.hardware.TalonFX;
import com.revrobotics.spark.ClosedLoopSlot;
import com.revrobotics.spark.SparkBase;
import com.revrobotics.spark.SparkClosedLoopController;
import com.revrobotics.spark.SparkFlex;
import com.revrobotics.spark.SparkLowLevel;
import cyberplanner.arm_cancel_t;
import cyberplanner.arm_plan_status_t;
import cyberplanner.roborio.ArmState;
import cyberplanner.roborio.Channels;
import cyberplanner.roborio.CyberPlannerClient;
import cyberplanner.roborio.Joint;
import cyberplanner.roborio.JointGravity;
import cyberplanner.roborio.MoveState;
import cyberplanner.roborio.Pose;
import cyberplanner.roborio.SetpointGuard.Verdict;
import cyberplanner.roborio.can.DaemonMode;
import cyberplanner.roborio.can.DaemonStatus;
import cyberplanner.roborio.can.FrcCanId;
import cyberplanner.roborio.can.Setpoint;
import cyberplanner.roborio.can.SetpointFrame;
import cyberplanner.roborio.can.StatusFrame;
import edu.wpi.first.hal.can.CANJNI;
import edu.wpi.first.wpilibj.CAN;
import edu.wpi.first.wpilibj.DriverStation;
import edu.wpi.first.wpilibj.RobotController;
import java.io.IOException;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import lcm.lcm.LCM;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * The WPILib 2026 layer on its stand-ins (src/standins2026): frames on the stand-in CAN stream
 * reach a TalonFX and a SparkFlex; the fallback, the cancel, the manual override and the health
 * counters of docs/roborio.md, "Safety".
 */
class Wpilib2026LayerTest {
  static final double JOINT0_KG = 0.37;
  static final double JOINT1_KG = 0.21;
  static final double JOINT1_ROTATIONS_PER_RAD = 1 / (2 * Math.PI);
  long nowMicros;
  final TalonFX joint0Motor = new TalonFX(11);
  final SparkFlex joint1Motor = new SparkFlex(12, SparkLowLevel.MotorType.kBrushless);
  ArmState measured = ArmState.of(0.30, 0.0, 1.50, 0.0);
  CanStreamSetpointSource source;
  CyberArmSubsystem subsystem;
  LCM lcm;
  final List<arm_cancel_t> cancels = new CopyOnWriteArrayList<>();

  /** The robot clock (µs) and the CAN timer (ms, another base: the layer must map between them). */
  void setTime(long micros) {
    nowMicros = micros;
    RobotController.standInFpgaTimeMicros = micros;
    CAN.standInTimeMs = 7_000 + micros / 1000;
  }

  /** A frame on the bus, received ageMicros ago. */
  void deliver(int apiId, int device, byte[] data, long ageMicros) {
    CANJNI.standInDeliver(FrcCanId.teamFrameId(apiId, device), data, CAN.standInTimeMs - ageMicros / 1000);
  }

  @BeforeEach
  void setUp() throws Exception {
    CANJNI.standInReset();
    DriverStation.standInEnabled = true;
    setTime(1_000_000);
    lcm = new LCM("memq://");
    lcm.subscribe("ARM_CANCEL", (l, c, in) -> {
      try {
        cancels.add(new arm_cancel_t(in));
      } catch (IOException e) {
        throw new AssertionError(e);
      }
    });
    CyberPlannerClient client = new CyberPlannerClient(lcm, Channels.DEFAULT, 1);
    source = CanStreamSetpointSource.withReferenceDevices();
    // Joint 0: 0.05 m per mechanism rotation; joint 1: a Spark encoder in rotations of the joint.
    subsystem = CyberArmSubsystem.create(client, source, new TalonFxOutput(joint0Motor, 20.0),
        new SparkOutput(joint1Motor, JOINT1_ROTATIONS_PER_RAD, ClosedLoopSlot.kSlot0), () -> measured,
        JointGravity.constant(JOINT0_KG), JointGravity.cosine(JOINT1_KG));
  }

  void deliverSetpoint(int device, double position, double velocity, double volts, int sequence, long ageMicros) {
    deliver(FrcCanId.SETPOINT_API_ID, device,
        SetpointFrame.encode(new Setpoint(device, position, velocity, volts, sequence)).value().data(), ageMicros);
  }

  void deliverStatus(DaemonMode mode, int sequence) {
    deliver(FrcCanId.STATUS_API_ID, 3, StatusFrame.encode(new DaemonStatus(3, mode, 1, 0, 0, sequence)).value().data(),
        0);
  }

  /** A status, both setpoints (0.37 V and 0.1 V) just received, then the robot loop. */
  void tick(DaemonMode mode, int sequence, double joint0M, double joint1Rad) {
    deliverStatus(mode, sequence);
    deliverSetpoint(1, joint0M, 0.0, 0.37, sequence, 0);
    deliverSetpoint(2, joint1Rad, 0.0, 0.1, sequence, 0);
    subsystem.periodic();
  }

  void assertHolding(double joint0M, double joint1Rad) {
    assertEquals(joint0M * 20.0, joint0Motor.standInPosition, 1e-9);
    assertEquals(0.0, joint0Motor.standInVelocity);
    assertEquals(JOINT0_KG, joint0Motor.standInFeedForward, 1e-9);
    SparkClosedLoopController spark = joint1Motor.getClosedLoopController();
    assertEquals(joint1Rad * JOINT1_ROTATIONS_PER_RAD, spark.standInValue, 1e-9);
    assertEquals(JOINT1_KG * Math.cos(joint1Rad), spark.standInArbFeedforward, 1e-9);
  }

  @Test
  void framesFromTheBusDriveTheTalonAndTheSpark() {
    deliverStatus(DaemonMode.MOVING, 0);
    deliverSetpoint(1, 0.5, 0.25, 0.37, 0, 0);
    deliverSetpoint(2, Math.PI, -1.0, -0.2, 0, 0);
    subsystem.periodic();
    assertEquals(Verdict.USE, subsystem.controller().verdict());
    assertEquals(10.0, joint0Motor.standInPosition, 1e-9);
    assertEquals(5.0, joint0Motor.standInVelocity, 1e-9);
    assertEquals(0.37, joint0Motor.standInFeedForward, 1e-9);
    SparkClosedLoopController spark = joint1Motor.getClosedLoopController();
    assertEquals(0.5, spark.standInValue, 1e-5);
    assertEquals(SparkBase.ControlType.kPosition, spark.standInControlType);
    assertEquals(ClosedLoopSlot.kSlot0, spark.standInSlot);
    assertEquals(-0.2, spark.standInArbFeedforward, 1e-9);
    assertEquals(SparkClosedLoopController.ArbFFUnits.kVoltage, spark.standInArbFFUnits);
  }

  @Test
  void staleSetpointsHoldWhereTheMechanismIsAgainstGravity() {
    tick(DaemonMode.MOVING, 0, 0.5, 1.0);
    measured = ArmState.of(0.47, 0.2, 1.1, 0.1);
    setTime(nowMicros + 60_000);  // no frames for 60 ms: older than the 50 ms limit
    subsystem.periodic();
    assertEquals(Verdict.SETPOINT_STALE, subsystem.controller().verdict());
    assertHolding(0.47, 1.1);
    tick(DaemonMode.MOVING, 1, 0.6, 1.1);
    assertEquals(Verdict.USE, subsystem.controller().verdict());
    assertEquals(12.0, joint0Motor.standInPosition, 1e-9);
  }

  @Test
  void theHoldIsCapturedAfreshOnEveryChangeToUnusable() {
    // No daemon from boot. Disabled, the mechanism sags from where it booted; enabled, it is held
    // where it stands, not driven back to the boot pose.
    DriverStation.standInEnabled = false;
    subsystem.periodic();
    measured = ArmState.of(0.05, 0.0, 1.2, 0.0);
    subsystem.periodic();
    DriverStation.standInEnabled = true;
    subsystem.periodic();
    assertEquals(Verdict.DAEMON_LOST, subsystem.controller().verdict());
    assertHolding(0.05, 1.2);
    // Setpoints in use move it; when they stop, the hold is where it is then.
    tick(DaemonMode.MOVING, 0, 0.8, 1.0);
    measured = ArmState.of(0.8, 0.0, 1.0, 0.0);
    setTime(nowMicros + 300_000);
    subsystem.periodic();
    assertEquals(Verdict.DAEMON_LOST, subsystem.controller().verdict());
    assertHolding(0.8, 1.0);
    measured = ArmState.of(0.7, 0.0, 0.9, 0.0);
    subsystem.periodic();
    assertHolding(0.8, 1.0);  // within one unusable stretch the hold stays put
  }

  @Test
  void aLosslessStreamPolledAt50HzLosesNoFrames() {
    int sequence = 0;
    for (int loop = 0; loop < 50; ++loop) {  // 1 s: 200 Hz frames, a 50 Hz robot loop
      deliverStatus(DaemonMode.MOVING, loop);
      for (int i = 3; i >= 0; --i, ++sequence) {
        boolean lost = loop == 30 && i == 2;  // one joint 0 frame lost on the bus
        if (!lost) deliverSetpoint(1, 0.5, 0.0, 0.37, sequence & 0xFF, i * 5_000L);
        deliverSetpoint(2, 1.0, 0.0, 0.1, sequence & 0xFF, i * 5_000L);
      }
      subsystem.periodic();
      setTime(nowMicros + 20_000);
    }
    assertEquals(1, subsystem.controller().guard().lostFrames(Joint.JOINT_0));
    assertEquals(0, subsystem.controller().guard().lostFrames(Joint.JOINT_1));
    assertEquals(Verdict.USE, subsystem.controller().verdict());
  }

  @Test
  void aSetpointsAgeCountsFromItsFrameTimestampNotFromThePoll() {
    deliverStatus(DaemonMode.HOLDING, 0);
    deliverSetpoint(1, 0.5, 0.0, 0.37, 0, 40_000);  // received 40 ms before this loop
    deliverSetpoint(2, 1.0, 0.0, 0.1, 0, 40_000);
    subsystem.periodic();
    assertEquals(Verdict.USE, subsystem.controller().verdict());
    setTime(nowMicros + 15_000);  // 55 ms old now
    subsystem.periodic();
    assertEquals(Verdict.SETPOINT_STALE, subsystem.controller().verdict());
  }

  @Test
  void malformedAndForeignFramesAreCountedNotApplied() {
    deliver(FrcCanId.SETPOINT_API_ID, 1, new byte[] {1, 2, 3}, 0);  // 3 bytes: wrong length
    deliver(FrcCanId.STATUS_API_ID, 3, new byte[] {9, 0, 0, 0, 0, 0, 0, 0}, 0);  // undefined mode
    deliverSetpoint(7, 0.5, 0.0, 0.0, 0, 0);  // a device that is not ours
    subsystem.periodic();
    assertEquals(2, source.router().undecodableFrames());
    assertEquals(1, source.router().foreignFrames());
    assertEquals(null, subsystem.controller().guard().latest(Joint.JOINT_0));
    assertEquals(Verdict.DAEMON_LOST, subsystem.controller().verdict());
  }

  @Test
  void interruptingTheCommandCancelsTheMoveAndTheDaemonHolds() throws Exception {
    MoveToPoseCommand move = subsystem.moveToCommand(Pose.of(1.22, 5.69));
    move.initialize();
    move.end(true);
    until(() -> cancels.size() == 1);
    assertEquals(move.move().requestId(), cancels.get(0).request_id);
    assertEquals(arm_cancel_t.ACTION_HOLD, cancels.get(0).action);
    // A move that ended by itself is not cancelled.
    MoveToPoseCommand done = subsystem.moveToCommand(Pose.of(0.2, 1.57));
    done.initialize();
    publishStatus(done.move().requestId(), arm_plan_status_t.STATUS_DONE, "");
    done.move().await(2);
    done.end(false);
    Thread.sleep(20);
    assertEquals(1, cancels.size());
  }

  @Test
  void aManualCommandReleasesTheDaemonAndOwnsTheMotorsUntilItEnds() throws Exception {
    tick(DaemonMode.MOVING, 0, 0.5, 1.0);
    int[] driven = {0};
    var manual = (ManualOverrideCommand) subsystem.manualCommand(() -> {
      driven[0]++;
      joint0Motor.standInPosition = -1.0;  // the team's own request
    });
    assertTrue(manual.getRequirements().contains(subsystem));
    manual.initialize();
    until(() -> cancels.size() == 1);
    assertEquals(-1, cancels.get(0).request_id);
    assertEquals(arm_cancel_t.ACTION_RELEASE, cancels.get(0).action);
    manual.execute();
    tick(DaemonMode.MOVING, 1, 0.9, 1.0);  // setpoints still on the bus: not applied
    assertEquals(-1.0, joint0Motor.standInPosition);
    assertEquals(1, driven[0]);
    manual.end(true);
    measured = ArmState.of(0.42, 0.0, 1.3, 0.0);
    tick(DaemonMode.RELEASED, 2, 0.9, 1.0);  // the daemon stopped streaming: hold where it is
    assertEquals(Verdict.DAEMON_NOT_STREAMING, subsystem.controller().verdict());
    assertHolding(0.42, 1.3);
  }

  @Test
  void theCommandFinishesOnDoneAndFailsOnRejection() throws Exception {
    MoveToPoseCommand move = subsystem.moveToCommand(Pose.of(1.22, 5.69));
    assertTrue(move.getRequirements().contains(subsystem));
    move.initialize();
    assertFalse(move.isFinished());
    publishStatus(move.move().requestId(), arm_plan_status_t.STATUS_DONE, "");
    assertEquals(MoveState.DONE, move.move().await(2));
    assertTrue(move.isFinished());
    assertTrue(move.succeeded());

    MoveToPoseCommand refused = subsystem.moveToCommand(Pose.of(0.0, 4.71));
    refused.initialize();
    publishStatus(refused.move().requestId(), arm_plan_status_t.STATUS_REJECTED, "goal in collision");
    refused.move().await(2);
    assertTrue(refused.isFinished());
    assertTrue(refused.failed());
    assertEquals("goal in collision", refused.reason());
  }

  void publishStatus(long requestId, byte status, String reason) {
    arm_plan_status_t m = new arm_plan_status_t();
    m.request_id = requestId;
    m.status = status;
    m.reason = reason;
    lcm.publish("ARM_PLAN_STATUS", m);
  }

  static void until(java.util.function.BooleanSupplier condition) throws InterruptedException {
    for (int i = 0; i < 400 && !condition.getAsBoolean(); ++i) Thread.sleep(5);
    assertTrue(condition.getAsBoolean(), "timed out");
  }
}
