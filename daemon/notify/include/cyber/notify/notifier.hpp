#pragma once
// The service manager's notification protocol (systemd's sd_notify), written here so the daemon
// needs no libsystemd: each notification is one datagram of "KEY=VALUE" lines sent to the
// AF_UNIX socket named by $NOTIFY_SOCKET ("/path", or "@name" for an abstract socket).
//
// Every send is non-blocking (MSG_DONTWAIT), never throws and never allocates; when the daemon
// is not run by a service manager (no $NOTIFY_SOCKET) every send is a cheap no-op.

#include <sys/socket.h>
#include <sys/un.h>

#include <chrono>
#include <cstddef>
#include <string_view>

namespace cyber::notify {

// What a send did. Callers normally ignore it (a lost notification is not an error of the
// daemon); tests and logs look at it.
enum class SendResult {
  sent,      // the whole datagram was queued on the manager's socket
  disabled,  // no usable $NOTIFY_SOCKET: nothing to do
  failed,    // the socket refused it (full queue, nobody bound, ...): dropped, never retried
};

std::string_view toString(SendResult result);

// One notification target: the parsed address and one datagram socket, opened by the
// constructor. Sends may come from several threads at once. Movable, not copyable.
class Notifier {
 public:
  // Disabled notifier: every send returns SendResult::disabled.
  Notifier() = default;
  // socket_name is the value of $NOTIFY_SOCKET: "/absolute/path" or "@abstract-name". Anything
  // else (empty, relative, too long for sockaddr_un) gives a disabled notifier.
  explicit Notifier(std::string_view socket_name);
  ~Notifier();
  Notifier(Notifier&& other) noexcept;
  Notifier& operator=(Notifier&& other) noexcept;
  Notifier(const Notifier&) = delete;
  Notifier& operator=(const Notifier&) = delete;

  // Reads $NOTIFY_SOCKET.
  static Notifier fromEnvironment();

  bool enabled() const { return fd_ >= 0; }

  SendResult ready();     // "READY=1": start-up finished (CAN bound, LCM good)
  SendResult watchdog();  // "WATCHDOG=1": still alive (see watchdogInterval)
  SendResult stopping();  // "STOPPING=1": clean shutdown begun
  // "STATUS=<text>": a one-line summary for `systemctl status`. Newlines in text become spaces
  // (a newline would start a new assignment) and text longer than kMaxStatusBytes is cut.
  SendResult status(std::string_view text);
  // "READY=1\nSTATUS=<text>" in one datagram, so the summary is there the moment the unit is up.
  SendResult readyWithStatus(std::string_view text);

  // Sends an already-formatted datagram as it is.
  SendResult sendRaw(std::string_view datagram);

  static constexpr std::size_t kMaxStatusBytes = 400;

 private:
  SendResult sendWithStatus(std::string_view prefix, std::string_view text);

  sockaddr_un address_{};
  socklen_t address_length_ = 0;
  int fd_ = -1;  // -1: disabled
};

// How often the manager expects WATCHDOG=1, from $WATCHDOG_USEC, or zero when no watchdog is
// asked for: $WATCHDOG_USEC missing or not a positive integer, or $WATCHDOG_PID set to another
// process. Ping at half this interval or faster.
std::chrono::microseconds watchdogInterval();
// The same rule on given values (nullptr = unset).
std::chrono::microseconds watchdogIntervalFrom(const char* watchdog_usec, const char* watchdog_pid, long own_pid);

// A process-wide notifier built from $NOTIFY_SOCKET on first use (thread-safe). Make the first
// call at start-up (e.g. notifyStatus("starting")), not on the streaming thread: it opens the
// socket.
SendResult notifyReady();
SendResult notifyWatchdog();
SendResult notifyStopping();
SendResult notifyStatus(std::string_view text);
SendResult notifyReadyWithStatus(std::string_view text);

}  // namespace cyber::notify
