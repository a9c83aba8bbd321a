#include "cyber/can/io_result.hpp"

#include <cerrno>
#include <cstring>

namespace cyber::can {

std::string errnoText(int error_number) {
  char buffer[256];
  // GNU strerror_r returns the text (possibly not in buffer).
  return ::strerror_r(error_number, buffer, sizeof buffer);
}

IoResult ioResultFromErrno(int error_number) {
  switch (error_number) {
    case EAGAIN: return IoResult{IoStatus::kWouldBlock, error_number};
    case ENOBUFS: return IoResult{IoStatus::kNoBufferSpace, error_number};
    case ENETDOWN: return IoResult{IoStatus::kNetworkDown, error_number};
    default: return IoResult{IoStatus::kError, error_number};
  }
}

std::string IoResult::message() const {
  switch (status) {
    case IoStatus::kOk: return "ok";
    case IoStatus::kWouldBlock: return "would block";
    case IoStatus::kNoBufferSpace: return "no buffer space (transmit queue full): " + errnoText(error_number);
    case IoStatus::kNetworkDown: return "network down: " + errnoText(error_number);
    case IoStatus::kError: return errnoText(error_number);
  }
  return errnoText(error_number);
}

}  // namespace cyber::can
