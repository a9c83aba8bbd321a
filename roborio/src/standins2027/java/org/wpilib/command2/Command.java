package org.wpilib.command2;

import java.util.HashSet;
import java.util.Set;

/** STAND-IN of WPILib 2027's command-based (org.wpilib.command2) Command (the methods the library uses; tests only). */
public abstract class Command {
  private final Set<Subsystem> requirements = new HashSet<>();

  public void initialize() {}

  public void execute() {}

  public void end(boolean interrupted) {}

  public boolean isFinished() {
    return false;
  }

  public final void addRequirements(Subsystem... subsystems) {
    requirements.addAll(Set.of(subsystems));
  }

  public Set<Subsystem> getRequirements() {
    return requirements;
  }
}
