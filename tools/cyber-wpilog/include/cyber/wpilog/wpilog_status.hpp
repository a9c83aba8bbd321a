#pragma once
// Why a WPILOG could not be read, written or converted from an LCM log: the status of every
// cyber::Result of this component, whose message says where and what.

namespace cyber::wpilog {

enum class WpilogStatus {
  kOk,
  kCannotOpen,          // the file cannot be opened for reading
  kBadMagic,            // not "WPILOG"
  kUnsupportedVersion,  // major version other than 1
  kTruncated,           // the file ends inside the header or a record
  kBadControlRecord,    // unknown control type or malformed Start/Finish/Set Metadata
  kUnknownEntry,        // a data record or Finish for an id that is not started
  kCannotWrite,         // the WPILOG file cannot be written
  kNoMessages,          // an LCM log without a decodable message of the channels
};

}  // namespace cyber::wpilog
