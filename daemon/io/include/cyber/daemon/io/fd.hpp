#pragma once
// The event loop's descriptors are the project's one set, cyber/posix/fd.hpp.

#include "cyber/posix/fd.hpp"

namespace cyber::daemon::io {

using posix::EventFd;
using posix::SignalFd;
using posix::TimerFd;
using posix::UniqueFd;

}  // namespace cyber::daemon::io
