package cyberplanner.roborio.can;

import java.util.Objects;

/** A decoded (or encoded) value, or the reason there is none. Never both, never neither. */
public final class Coded<T> {
  private final T value;
  private final CodecError error;

  private Coded(T value, CodecError error) {
    this.value = value;
    this.error = error;
  }

  public static <T> Coded<T> of(T value) {
    return new Coded<>(Objects.requireNonNull(value), null);
  }

  public static <T> Coded<T> failure(CodecError error) {
    return new Coded<>(null, Objects.requireNonNull(error));
  }

  public boolean ok() {
    return error == null;
  }

  /** The value; throws if there is none (check {@link #ok()} first). */
  public T value() {
    if (error != null) throw new IllegalStateException("no value: " + error);
    return value;
  }

  /** The error, or null when {@link #ok()}. */
  public CodecError error() {
    return error;
  }
}
