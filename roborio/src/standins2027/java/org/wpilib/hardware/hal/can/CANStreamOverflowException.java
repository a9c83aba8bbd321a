package org.wpilib.hardware.hal.can;

import java.io.IOException;

/**
 * STAND-IN of WPILib 2027's CANStreamOverflowException (tests only), its signature from
 * allwpilib `main`, commit caf0fb2dccb462a1507888246646daa5ba38cd82:
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
