#pragma once
// A non-blocking SocketCAN raw socket bound to one interface. No exceptions: open() returns an
// OpenError with a message that names the interface and the cause, read()/write() an IoResult the
// caller can count without allocating.

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "cyber/can/frame.hpp"
#include "cyber/can/id_filter.hpp"
#include "cyber/can/io_result.hpp"
#include "cyber/result.hpp"

namespace cyber::can {

struct SocketOptions {
  // nullopt: receive every data frame; an empty list: receive none. Each user passes its own.
  std::optional<std::vector<IdFilter>> filters;
  // Deliver error frames for bus-off, controller problems, tx timeouts and restarts.
  bool receive_bus_errors = true;
};

enum class OpenError {
  kOk,
  kInvalidName,       // empty, too long, or containing '/' or white space
  kKernelWithoutCan,  // socket(PF_CAN) not supported: no can / can-raw modules
  kNoSuchInterface,   // no network interface of that name
  kSetupFailed,       // a socket option or bind() failed
};

class CanSocket {
 public:
  static Result<CanSocket, OpenError> open(std::string_view ifname, const SocketOptions& options = {});
  // Takes ownership of an already open descriptor (tests use a socketpair in place of CAN).
  static CanSocket adopt(int fd) { return CanSocket(fd); }

  CanSocket(CanSocket&& other) noexcept;
  CanSocket& operator=(CanSocket&& other) noexcept;
  CanSocket(const CanSocket&) = delete;
  CanSocket& operator=(const CanSocket&) = delete;
  ~CanSocket();

  int fd() const { return fd_; }  // for poll/epoll; stays owned by this object

  // One frame, without blocking. Frames the kernel hands over are always accepted: error frames
  // come back with frame.error set.
  IoResult read(Frame& frame);
  // One frame, without blocking. The frame should be well-formed (isWellFormed).
  IoResult write(const Frame& frame);

 private:
  explicit CanSocket(int fd) : fd_(fd) {}
  void close();

  int fd_ = -1;
};

}  // namespace cyber::can
