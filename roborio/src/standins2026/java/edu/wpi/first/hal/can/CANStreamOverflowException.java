package edu.wpi.first.hal.can;

import edu.wpi.first.hal.CANStreamMessage;
import java.io.IOException;

/** STAND-IN of WPILib 2026's CANStreamOverflowException (tests only). */
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
