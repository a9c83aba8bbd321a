package edu.wpi.first.hal.can;

import edu.wpi.first.hal.CANStreamMessage;
import java.io.IOException;

/**
 * STAND-IN of WPILib 2026's CANStreamOverflowException (tests only), its signature from
 * allwpilib branch `2026`, commit 5cffd78c06c7585a85002fac422ac8a2b04e5489:
 * the array read into and how many of its messages are valid. The stand-in CANJNI throws it when
 * the session's buffer overflowed.
 */
public class CANStreamOverflowException extends IOException {
  private static final long serialVersionUID = 1L;
  private final CANStreamMessage[] messages;
  private final int messagesRead;

  public CANStreamOverflowException(CANStreamMessage[] messages, int messagesRead) {
    super("stand-in: stream overflow");
    this.messages = messages;
    this.messagesRead = messagesRead;
  }

  public CANStreamMessage[] getMessages() {
    return messages;
  }

  public int getMessagesRead() {
    return messagesRead;
  }
}
