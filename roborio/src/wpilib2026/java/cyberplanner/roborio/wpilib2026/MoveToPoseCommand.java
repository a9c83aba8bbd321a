package cyberplanner.roborio.wpilib2026;

import cyberplanner.roborio.MoveHandle;
import cyberplanner.roborio.MoveState;
import cyberplanner.roborio.Pose;
import edu.wpi.first.wpilibj2.command.Command;

/**
 * Moves to a pose through cyber-plannerd: sends the goal when scheduled and finishes when the move
 * is finished. Interrupted (a released whileTrue button, another command taking the subsystem),
 * it cancels the move: the daemon brakes to rest and holds there. It succeeded only when the move
 * is DONE; failed() and reason() tell REJECTED, FAILED or CANCELLED.
 */
public class MoveToPoseCommand extends Command {
  private final CyberArmSubsystem subsystem;
  private final Pose pose;
  private MoveHandle move;

  public MoveToPoseCommand(CyberArmSubsystem subsystem, Pose pose) {
    this.subsystem = subsystem;
    this.pose = pose;
    addRequirements(subsystem);
  }

  @Override
  public void initialize() {
    move = subsystem.moveTo(pose);
  }

  @Override
  public boolean isFinished() {
    return move != null && move.isFinished();
  }

  @Override
  public void end(boolean interrupted) {
    if (interrupted) subsystem.controller().cancel(move);
  }

  /** The current move, or null before the command first ran. */
  public MoveHandle move() {
    return move;
  }

  public boolean succeeded() {
    return move != null && move.state() == MoveState.DONE;
  }

  public boolean failed() {
    return move != null && move.isFinished() && move.state() != MoveState.DONE;
  }

  public String reason() {
    return move == null ? "" : move.reason();
  }
}
