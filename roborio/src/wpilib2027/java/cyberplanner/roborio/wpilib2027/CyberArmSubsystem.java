package cyberplanner.roborio.wpilib2027;

import cyberplanner.roborio.ArmController;
import cyberplanner.roborio.ArmState;
import cyberplanner.roborio.CyberPlannerClient;
import cyberplanner.roborio.JointGravity;
import cyberplanner.roborio.JointOutput;
import cyberplanner.roborio.MoveHandle;
import cyberplanner.roborio.Pose;
import cyberplanner.roborio.SetpointSource;
import java.util.function.Supplier;
import org.wpilib.command2.Command;
import org.wpilib.command2.SubsystemBase;
import org.wpilib.driverstation.RobotState;
import org.wpilib.system.RobotController;

/**
 * A two-joint mechanism driven by cyber-plannerd on a Systemcore (WPILib 2027, docs/roborio.md): a
 * command-based subsystem around the WPILib-free ArmController, whose periodic() it runs.
 */
public class CyberArmSubsystem extends SubsystemBase {
  private final ArmController controller;

  public CyberArmSubsystem(ArmController controller) {
    this.controller = controller;
  }

  /**
   * The usual wiring: enabled from RobotState, the robot clock (µs, monotonic), the default guard
   * and a hold against gravity (the kG and shape of each joint's [drives.*] in the daemon's config).
   * joint0 and joint1 drive the config's first and second [[joints]].
   */
  public static CyberArmSubsystem create(CyberPlannerClient client, SetpointSource source, JointOutput joint0,
      JointOutput joint1, Supplier<ArmState> measured, JointGravity joint0Gravity, JointGravity joint1Gravity) {
    return new CyberArmSubsystem(new ArmController(new ArmController.Parts(client, source, joint0, joint1, measured,
        RobotState::isEnabled, RobotController::getTime), joint0Gravity, joint1Gravity));
  }

  @Override
  public void periodic() {
    controller.periodic();
  }

  public ArmController controller() {
    return controller;
  }

  public MoveHandle moveTo(Pose pose) {
    return controller.moveTo(pose);
  }

  /** Moves to pose; interrupted, it cancels the move (the daemon brakes and holds). */
  public MoveToPoseCommand moveToCommand(Pose pose) {
    return new MoveToPoseCommand(this, pose);
  }

  /** Runs drive every loop while the daemon stands back (manual override, docs/roborio.md). */
  public Command manualCommand(Runnable drive) {
    return new ManualOverrideCommand(this, drive);
  }
}
