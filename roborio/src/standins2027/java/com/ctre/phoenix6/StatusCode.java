package com.ctre.phoenix6;

/** STAND-IN of Phoenix 6's StatusCode (tests only). */
public enum StatusCode {
  OK
}
