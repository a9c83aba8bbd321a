package cyberplanner.roborio;

/** The measured state the robot publishes on ARM_STATE (m, m/s, rad, rad/s, pieces held). */
public record ArmState(double elevatorM, double elevatorMps, double armRad, double armRadps, boolean heldCoral,
    boolean heldAlgae) {}
