#include "cyber/daemon/io/process_signals.hpp"

#include <csignal>

namespace cyber::daemon::io {

void ignoreHangupAndPipe() {
  std::signal(SIGHUP, SIG_IGN);
  std::signal(SIGPIPE, SIG_IGN);
}

}  // namespace cyber::daemon::io
