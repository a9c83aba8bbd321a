package cyberplanner.roborio.wpilib;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.ctre.phoenix6.hardware.TalonFX;
import com.revrobotics.spark.ClosedLoopSlot;
import com.revrobotics.spark.SparkBase;
import com.revrobotics.spark.SparkClosedLoopController;
import com.revrobotics.spark.SparkFlex;
import com.revrobotics.spark.SparkLowLevel;
import cyberplanner.arm_plan_status_t;
import cyberplanner.roborio.ArmState;
import cyberplanner.roborio.Channels;
import cyberplanner.roborio.CyberPlannerClient;
import cyberplanner.roborio.MoveState;
import cyberplanner.roborio.Pose;
import cyberplanner.roborio.SetpointGuard;
import cyberplanner.roborio.can.DaemonMode;
import cyberplanner.roborio.can.DaemonStatus;
import cyberplanner.roborio.can.FrcCanId;
import cyberplanner.roborio.can.Setpoint;
import cyberplanner.roborio.can.SetpointFrame;
import cyberplanner.roborio.can.StatusFrame;
import edu.wpi.first.wpilibj.CAN;
import lcm.lcm.LCM;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * The WPILib layer against the stand-ins (src/standins): frames delivered through the stand-in
 * CAN class reach a TalonFX and a SparkFlex, and the fallback holds when they stop.
 */
class WpilibLayerTest {
  long nowMicros = 1_000_000;
  final TalonFX elevatorMotor = new TalonFX(11);
  final SparkFlex armMotor = new SparkFlex(12, SparkLowLevel.MotorType.kBrushless);
  final ArmState measured = new ArmState(0.30, 0.0, 1.50, 0.0, false, false);
  CyberArmSubsystem subsystem;
  LCM lcm;

  @BeforeEach
  void setUp() throws Exception {
    CAN.standInReset();
    lcm = new LCM("memq://");
    CyberPlannerClient client = new CyberPlannerClient(lcm, Channels.DEFAULT, 1);
    // Elevator: 0.05 m per mechanism rotation; arm: Spark encoder in rotations of the arm.
    subsystem = new CyberArmSubsystem(client, CanSetpointSource.withReferenceDevices(),
        new TalonFxOutput(elevatorMotor, 20.0), new SparkOutput(armMotor, 1 / (2 * Math.PI), ClosedLoopSlot.kSlot0),
        () -> measured, new SetpointGuard(0.05, 0.25), new HoldFallback(new TalonFxOutput(elevatorMotor, 20.0),
            new SparkOutput(armMotor, 1 / (2 * Math.PI), ClosedLoopSlot.kSlot0)),
        () -> nowMicros);
  }

  static void deliver(int apiId, int device, byte[] data) {
    CAN.standInDeliver(FrcCanId.DEVICE_TYPE_MISCELLANEOUS, FrcCanId.MANUFACTURER_TEAM_USE, apiId, device, data);
  }

  static void deliverSetpoint(int device, double position, double velocity, double volts, int sequence) {
    deliver(FrcCanId.SETPOINT_API_ID, device,
        SetpointFrame.encode(new Setpoint(device, position, velocity, volts, sequence)).value().data());
  }

  static void deliverStatus(DaemonMode mode, int sequence) {
    deliver(FrcCanId.STATUS_API_ID, 3, StatusFrame.encode(new DaemonStatus(3, mode, 1, 0, 0, sequence)).value().data());
  }

  /** One stream period on the bus: a status, both setpoints (0.37 V and 0.1 V), then the robot loop. */
  void tick(DaemonMode mode, int sequence, double elevatorM, double armRad) {
    deliverStatus(mode, sequence);
    deliverSetpoint(1, elevatorM, 0.0, 0.37, sequence);
    deliverSetpoint(2, armRad, 0.0, 0.1, sequence);
    subsystem.periodic();
  }

  @Test
  void framesFromTheBusDriveTheTalonAndTheSpark() {
    deliverStatus(DaemonMode.MOVING, 0);
    deliverSetpoint(1, 0.5, 0.25, 0.37, 0);
    deliverSetpoint(2, Math.PI, -1.0, -0.2, 0);
    subsystem.periodic();
    assertEquals(SetpointGuard.Verdict.USE, subsystem.verdict());
    assertEquals(10.0, elevatorMotor.standInPosition, 1e-9);
    assertEquals(5.0, elevatorMotor.standInVelocity, 1e-9);
    assertEquals(0.37, elevatorMotor.standInFeedForward, 1e-9);
    SparkClosedLoopController arm = armMotor.getClosedLoopController();
    assertEquals(0.5, arm.standInValue, 1e-5);
    assertEquals(SparkBase.ControlType.kPosition, arm.standInControlType);
    assertEquals(ClosedLoopSlot.kSlot0, arm.standInSlot);
    assertEquals(-0.2, arm.standInArbFeedforward, 1e-9);
    assertEquals(SparkClosedLoopController.ArbFFUnits.kVoltage, arm.standInArbFFUnits);
  }

  @Test
  void staleSetpointsHoldTheMeasuredPositionUntilFreshOnesArrive() {
    tick(DaemonMode.MOVING, 0, 0.5, 1.0);
    nowMicros += 60_000;  // no frames for 60 ms: older than the 50 ms limit
    subsystem.periodic();
    assertEquals(SetpointGuard.Verdict.SETPOINT_STALE, subsystem.verdict());
    assertEquals(0.30 * 20.0, elevatorMotor.standInPosition, 1e-9);
    assertEquals(0.0, elevatorMotor.standInVelocity);
    assertEquals(1.50 / (2 * Math.PI), armMotor.getClosedLoopController().standInValue, 1e-9);
    tick(DaemonMode.MOVING, 1, 0.6, 1.1);
    assertEquals(SetpointGuard.Verdict.USE, subsystem.verdict());
    assertEquals(12.0, elevatorMotor.standInPosition, 1e-9);
  }

  @Test
  void aDisabledRobotOrALostDaemonFallsBack() {
    tick(DaemonMode.ROBOT_DISABLED, 0, 0.5, 1.0);
    assertEquals(SetpointGuard.Verdict.DAEMON_NOT_STREAMING, subsystem.verdict());
    assertEquals(6.0, elevatorMotor.standInPosition, 1e-9);
    nowMicros += 300_000;
    subsystem.periodic();
    assertEquals(SetpointGuard.Verdict.DAEMON_LOST, subsystem.verdict());
  }

  @Test
  void malformedFramesAreCountedNotApplied() {
    CanSetpointSource source = new CanSetpointSource(1, 2, 3);
    deliver(FrcCanId.SETPOINT_API_ID, 1, new byte[] {1, 2, 3});  // 3 bytes: wrong length
    deliver(FrcCanId.STATUS_API_ID, 3, new byte[] {9, 0, 0, 0, 0, 0, 0, 0});  // undefined mode
    SetpointGuard guard = new SetpointGuard(0.05, 0.25);
    source.poll(guard, 0);
    assertEquals(2, source.undecodableFrames());
    assertEquals(null, guard.latest(cyberplanner.roborio.Joint.ELEVATOR));
    assertEquals(SetpointGuard.Verdict.DAEMON_LOST, guard.verdict(0));
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
}
