package com.revrobotics.spark;

/** STAND-IN of REVLib's ClosedLoopSlot (tests only). */
public enum ClosedLoopSlot {
  kSlot0,
  kSlot1,
  kSlot2,
  kSlot3
}
