#pragma once
// Signals the daemon survives (docs/operations.md, "Signals"):
//   SIGHUP is ignored: the configuration is read once at start-up (a new one needs a restart,
//   which re-plans from the measured state). Its default action would kill the daemon without the
//   clean hold SIGTERM gives, e.g. when the terminal it was started from goes away.
//   SIGPIPE is ignored: a log reader that goes away (journald restarting, `| head`) makes writes to
//   stderr fail with EPIPE, which the logger drops, instead of killing the daemon.

namespace cyber::daemon::io {

// Call in main() before any thread starts (the dispositions are process-wide).
void ignoreHangupAndPipe();

}  // namespace cyber::daemon::io
