#include "cyber/daemon/stream_event.hpp"

namespace cyber::daemon {

std::string_view toString(StreamEventKind kind) {
  switch (kind) {
    case StreamEventKind::kAdopted: return "adopted";
    case StreamEventKind::kRejected: return "rejected";
    case StreamEventKind::kExecuting: return "executing";
    case StreamEventKind::kDone: return "done";
    case StreamEventKind::kStopped: return "stopped";
    case StreamEventKind::kHolding: return "holding";
    case StreamEventKind::kFault: return "fault";
  }
  return "unknown";
}

std::string_view toString(RejectReason reason) {
  switch (reason) {
    case RejectReason::kLate: return "late: the splice time had already passed";
    case RejectReason::kStaleBase: return "stale: built on a program that is no longer running";
  }
  return "unknown";
}

}  // namespace cyber::daemon
