package cyberplanner.roborio.wpilib2027;

import org.wpilib.command2.Command;

/**
 * A team's own command on the joints (docs/roborio.md, "Manual override"): while it runs, the
 * daemon is released (it stops streaming) and the subsystem applies neither setpoints nor its
 * fallback; drive runs every loop and commands the motors. When it ends, the fallback holds where
 * the joints are until the next goal.
 */
public class ManualOverrideCommand extends Command {
  private final CyberArmSubsystem subsystem;
  private final Runnable drive;

  public ManualOverrideCommand(CyberArmSubsystem subsystem, Runnable drive) {
    this.subsystem = subsystem;
    this.drive = drive;
    addRequirements(subsystem);
  }

  @Override
  public void initialize() {
    subsystem.controller().beginManualOverride();
  }

  @Override
  public void execute() {
    drive.run();
  }

  @Override
  public void end(boolean interrupted) {
    subsystem.controller().endManualOverride();
  }
}
