#pragma once
// spdlog set-up for the daemon: one asynchronous logger writing to stderr (journald keeps it under
// systemd), so no thread waits on the terminal. The streamer thread never logs at all.

#include <string>

namespace cyber::daemon::io {

// Installs the default logger; false when `level` is not a spdlog level name.
bool setupLogging(const std::string& level);
void flushLogging();

}  // namespace cyber::daemon::io
