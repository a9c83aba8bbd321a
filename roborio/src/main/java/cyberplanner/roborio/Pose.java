package cyberplanner.roborio;

/**
 * A target of the elevator and arm (the planner's joint coordinates, docs/lcm.md): elevator
 * extension along its rail in m, arm angle in rad, the game pieces held during the move, and a
 * named obstacle scene of the daemon's config ("" = its default).
 */
public record Pose(double elevatorM, double armRad, boolean heldCoral, boolean heldAlgae, String sceneName) {
  public Pose {
    if (sceneName == null) sceneName = "";
  }

  public static Pose of(double elevatorM, double armRad) {
    return new Pose(elevatorM, armRad, false, false, "");
  }

  public Pose withCoral() {
    return new Pose(elevatorM, armRad, true, heldAlgae, sceneName);
  }

  public Pose withAlgae() {
    return new Pose(elevatorM, armRad, heldCoral, true, sceneName);
  }
}
