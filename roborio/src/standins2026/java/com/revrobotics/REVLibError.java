package com.revrobotics;

/** STAND-IN of REVLib's REVLibError (tests only). */
public enum REVLibError {
  kOk
}
