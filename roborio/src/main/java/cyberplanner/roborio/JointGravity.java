package cyberplanner.roborio;

/**
 * The gravity term of one joint's feedforward, kG·g(q), as the daemon's config models it
 * ([drives.*] gravity and kG_volts, docs/configuration.md): g = 1 ("constant", a joint that
 * moves vertically, such as a lift), g = cos θ ("cosine", a joint that swings, θ in rad from the
 * horizontal).
 */
public record JointGravity(double kGVolts, boolean cosine) {
  public static JointGravity constant(double kGVolts) {
    return new JointGravity(kGVolts, false);
  }

  public static JointGravity cosine(double kGVolts) {
    return new JointGravity(kGVolts, true);
  }

  /** No gravity term (a joint the controller's own kG holds). */
  public static final JointGravity NONE = constant(0.0);

  /** The volts that hold the joint still at position (m or rad). */
  public double volts(double position) {
    return cosine ? kGVolts * Math.cos(position) : kGVolts;
  }
}
