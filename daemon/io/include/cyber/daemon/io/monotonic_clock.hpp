#pragma once
// The real CLOCK_MONOTONIC, read only by the I/O layer: the daemon's logic takes "now" as a
// parameter (mono_time.hpp).

#include "cyber/daemon/mono_time.hpp"

namespace cyber::daemon::io {

MonoNs monotonicNow();

}  // namespace cyber::daemon::io
