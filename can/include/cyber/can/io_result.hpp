#pragma once
// The outcome of one non-blocking frame read or write: a value the caller can count without
// allocating. Shared by the CAN socket and the daemon's frame ports, which must not depend on
// the socket itself.

#include <string>

namespace cyber::can {

enum class IoStatus {
  kOk,
  kWouldBlock,     // EAGAIN: nothing to read / transmit queue full for now
  kNoBufferSpace,  // ENOBUFS: the driver's queue is full (bus down or flooded)
  kNetworkDown,    // ENETDOWN: the interface is down
  kError,          // anything else; error_number tells
};

struct IoResult {
  IoStatus status = IoStatus::kOk;
  int error_number = 0;  // errno for kNoBufferSpace/kNetworkDown/kError; EMSGSIZE for short I/O

  bool ok() const { return status == IoStatus::kOk; }
  std::string message() const;  // allocates: for logs, not for the streaming path
};

// The IoResult of a failed read()/write() with this errno.
IoResult ioResultFromErrno(int error_number);

// strerror_r's text for an errno value.
std::string errnoText(int error_number);

}  // namespace cyber::can
