package cyberplanner.roborio;

/** The two joints cyber-plannerd commands: elevator (m) and arm (rad). */
public enum Joint {
  ELEVATOR,
  ARM
}
