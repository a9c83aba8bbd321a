#include "cyber/can/can_socket.hpp"

#include <linux/can.h>
#include <linux/can/error.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <sys/socket.h>
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "cyber/can/linux_frame.hpp"

namespace cyber::can {

namespace {

// The message names the interface and the cause, with errno's text when a system call failed.
Error<OpenError> openError(OpenError kind, int error_number, std::string_view ifname, std::string_view what) {
  std::string message = "CAN interface '" + std::string(ifname) + "': " + std::string(what);
  if (error_number != 0) message += " (" + errnoText(error_number) + ")";
  return Error<OpenError>{kind, std::move(message)};
}

bool validInterfaceName(std::string_view name) {
  if (name.empty() || name.size() >= IFNAMSIZ) return false;
  for (char c : name) {
    if (c == '/' || c == ' ' || c == '\t' || c == '\n' || c == '\0') return false;
  }
  return true;
}

}  // namespace

Result<CanSocket, OpenError> CanSocket::open(std::string_view ifname, const SocketOptions& options) {
  if (!validInterfaceName(ifname)) {
    return openError(OpenError::kInvalidName, 0, ifname,
                     "invalid interface name (1 to 15 characters, no '/' or white space)");
  }
  const std::string name(ifname);

  const int fd = ::socket(PF_CAN, SOCK_RAW | SOCK_NONBLOCK | SOCK_CLOEXEC, CAN_RAW);
  if (fd < 0) {
    const int error_number = errno;
    if (error_number == EAFNOSUPPORT) {
      return openError(OpenError::kKernelWithoutCan, error_number, ifname,
                       "address family not supported (kernel without CAN: load the can and "
                       "can-raw modules)");
    }
    if (error_number == EPROTONOSUPPORT) {
      return openError(OpenError::kKernelWithoutCan, error_number, ifname,
                       "protocol not supported (kernel without CAN_RAW: load the can-raw module)");
    }
    return openError(OpenError::kSetupFailed, error_number, ifname, "socket(PF_CAN) failed");
  }
  CanSocket socket(fd);  // closes fd on every early return below

  const unsigned index = ::if_nametoindex(name.c_str());
  if (index == 0) {
    return openError(OpenError::kNoSuchInterface, errno, ifname, "no such interface");
  }

  if (options.filters) {
    std::vector<can_filter> kernel_filters;
    kernel_filters.reserve(options.filters->size());
    for (const IdFilter& filter : *options.filters) {
      kernel_filters.push_back(toKernelFilter(filter));
    }
    const auto bytes = static_cast<socklen_t>(kernel_filters.size() * sizeof(can_filter));
    if (::setsockopt(fd, SOL_CAN_RAW, CAN_RAW_FILTER, kernel_filters.empty() ? nullptr : kernel_filters.data(),
                     bytes) != 0) {
      return openError(OpenError::kSetupFailed, errno, ifname, "setting CAN_RAW_FILTER failed");
    }
  }
  const can_err_mask_t error_mask =
      options.receive_bus_errors ? (CAN_ERR_BUSOFF | CAN_ERR_CRTL | CAN_ERR_TX_TIMEOUT | CAN_ERR_RESTARTED) : 0;
  if (::setsockopt(fd, SOL_CAN_RAW, CAN_RAW_ERR_FILTER, &error_mask, sizeof error_mask) != 0) {
    return openError(OpenError::kSetupFailed, errno, ifname, "setting CAN_RAW_ERR_FILTER failed");
  }

  sockaddr_can address{};
  address.can_family = AF_CAN;
  address.can_ifindex = static_cast<int>(index);
  if (::bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
    return openError(OpenError::kSetupFailed, errno, ifname, "bind failed");
  }
  return socket;
}

CanSocket::CanSocket(CanSocket&& other) noexcept : fd_(other.fd_) { other.fd_ = -1; }

CanSocket& CanSocket::operator=(CanSocket&& other) noexcept {
  if (this != &other) {
    close();
    fd_ = other.fd_;
    other.fd_ = -1;
  }
  return *this;
}

CanSocket::~CanSocket() { close(); }

void CanSocket::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

IoResult CanSocket::read(Frame& frame) {
  can_frame raw;
  ssize_t got;
  do {
    got = ::read(fd_, &raw, sizeof raw);
  } while (got < 0 && errno == EINTR);
  if (got < 0) return ioResultFromErrno(errno);
  // A raw socket hands over whole frames; anything shorter is not a classic CAN frame.
  if (static_cast<std::size_t>(got) != sizeof raw) return IoResult{IoStatus::kError, EMSGSIZE};
  const auto converted = fromLinuxFrame(raw);
  if (!converted) return IoResult{IoStatus::kError, EMSGSIZE};
  frame = converted.value();
  return IoResult{};
}

IoResult CanSocket::write(const Frame& frame) {
  const can_frame raw = toLinuxFrame(frame);
  ssize_t put;
  do {
    put = ::write(fd_, &raw, sizeof raw);
  } while (put < 0 && errno == EINTR);
  if (put < 0) return ioResultFromErrno(errno);
  if (static_cast<std::size_t>(put) != sizeof raw) return IoResult{IoStatus::kError, EMSGSIZE};
  return IoResult{};
}

}  // namespace cyber::can
