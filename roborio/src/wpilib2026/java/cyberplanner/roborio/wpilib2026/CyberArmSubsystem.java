package cyberplanner.roborio.wpilib2026;

import cyberplanner.roborio.ArmController;
import cyberplanner.roborio.ArmState;
import cyberplanner.roborio.CyberPlannerClient;
import cyberplanner.roborio.JointGravity;
import cyberplanner.roborio.JointOutput;
import cyberplanner.roborio.MoveHandle;
import cyberplanner.roborio.Pose;
import cyberplanner.roborio.SetpointSource;
import edu.wpi.first.wpilibj.DriverStation;
import edu.wpi.first.wpilibj.RobotController;
import edu.wpi.first.wpilibj2.command.Command;
import edu.wpi.first.wpilibj2.command.SubsystemBase;
import java.util.function.Supplier;

/**
 * A two-joint mechanism driven by cyber-plannerd on a roboRIO (WPILib 2026, docs/roborio.md): a
 * command-based subsystem around the WPILib-free ArmController, whose periodic() it runs.
 */
public class CyberArmSubsystem extends SubsystemBase {
  private final ArmController controller;

  public CyberArmSubsystem(ArmController controller) {
    this.controller = controller;
  }

  /**
   * The usual wiring: enabled from the DriverStation, the FPGA clock, the default guard and a
   * hold against gravity (the kG and shape of each joint's [drives.*] in the daemon's config).
   * joint0 and joint1 drive the config's first and second [[joints]].
   */
  public static CyberArmSubsystem create(CyberPlannerClient client, SetpointSource source, JointOutput joint0,
      JointOutput joint1, Supplier<ArmState> measured, JointGravity joint0Gravity, JointGravity joint1Gravity) {
    return new CyberArmSubsystem(new ArmController(new ArmController.Parts(client, source, joint0, joint1, measured,
        DriverStation::isEnabled, RobotController::getFPGATime), joint0Gravity, joint1Gravity));
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
