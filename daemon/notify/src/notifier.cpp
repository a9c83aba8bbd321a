#include "cyber/notify/notifier.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <utility>

namespace cyber::notify {

std::string_view toString(SendResult result) {
  switch (result) {
    case SendResult::sent: return "sent";
    case SendResult::disabled: return "disabled";
    case SendResult::failed: return "failed";
  }
  return "unknown";
}

Notifier::Notifier(std::string_view socket_name) {
  // sun_path holds the name; an abstract name has a leading NUL instead of '@' and is not
  // NUL-terminated, so its address length counts exactly its bytes.
  const bool is_path = !socket_name.empty() && socket_name.front() == '/';
  const bool is_abstract = socket_name.size() > 1 && socket_name.front() == '@';
  if (!is_path && !is_abstract) return;
  const std::size_t room = sizeof(address_.sun_path) - (is_path ? 1 : 0);
  if (socket_name.size() > room) return;

  address_.sun_family = AF_UNIX;
  std::memcpy(address_.sun_path, socket_name.data(), socket_name.size());
  if (is_abstract) address_.sun_path[0] = '\0';
  address_length_ = static_cast<socklen_t>(offsetof(sockaddr_un, sun_path) + socket_name.size() + (is_path ? 1 : 0));
  fd_ = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
}

Notifier::~Notifier() {
  if (fd_ >= 0) ::close(fd_);
}

Notifier::Notifier(Notifier&& other) noexcept
    : address_(other.address_),
      address_length_(std::exchange(other.address_length_, 0)),
      fd_(std::exchange(other.fd_, -1)) {}

Notifier& Notifier::operator=(Notifier&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    address_ = other.address_;
    address_length_ = std::exchange(other.address_length_, 0);
    fd_ = std::exchange(other.fd_, -1);
  }
  return *this;
}

Notifier Notifier::fromEnvironment() {
  const char* name = std::getenv("NOTIFY_SOCKET");
  return name == nullptr ? Notifier() : Notifier(name);
}

SendResult Notifier::sendRaw(std::string_view datagram) {
  if (fd_ < 0) return SendResult::disabled;
  const auto* target = reinterpret_cast<const sockaddr*>(&address_);
  ssize_t written = -1;
  do {
    written = ::sendto(fd_, datagram.data(), datagram.size(), MSG_DONTWAIT | MSG_NOSIGNAL, target, address_length_);
  } while (written < 0 && errno == EINTR);
  return written == static_cast<ssize_t>(datagram.size()) ? SendResult::sent : SendResult::failed;
}

SendResult Notifier::ready() { return sendRaw("READY=1"); }
SendResult Notifier::watchdog() { return sendRaw("WATCHDOG=1"); }
SendResult Notifier::stopping() { return sendRaw("STOPPING=1"); }
SendResult Notifier::status(std::string_view text) { return sendWithStatus("STATUS=", text); }
SendResult Notifier::readyWithStatus(std::string_view text) { return sendWithStatus("READY=1\nSTATUS=", text); }

SendResult Notifier::sendWithStatus(std::string_view prefix, std::string_view text) {
  if (fd_ < 0) return SendResult::disabled;
  char buffer[32 + kMaxStatusBytes];
  static_assert(sizeof("READY=1\nSTATUS=") <= 32);
  std::memcpy(buffer, prefix.data(), prefix.size());
  const std::size_t text_bytes = std::min(text.size(), kMaxStatusBytes);
  std::replace_copy(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(text_bytes), buffer + prefix.size(), '\n',
                    ' ');
  return sendRaw(std::string_view(buffer, prefix.size() + text_bytes));
}

std::chrono::microseconds watchdogIntervalFrom(const char* watchdog_usec, const char* watchdog_pid, long own_pid) {
  const auto parse = [](const char* text, long long& value) {
    const char* end = text + std::strlen(text);
    const auto [ptr, error] = std::from_chars(text, end, value);
    return error == std::errc() && ptr == end && ptr != text;
  };
  if (watchdog_usec == nullptr) return std::chrono::microseconds(0);
  long long usec = 0;
  if (!parse(watchdog_usec, usec) || usec <= 0) return std::chrono::microseconds(0);
  if (watchdog_pid != nullptr) {
    long long pid = 0;
    if (!parse(watchdog_pid, pid) || pid != own_pid) return std::chrono::microseconds(0);
  }
  return std::chrono::microseconds(usec);
}

std::chrono::microseconds watchdogInterval() {
  return watchdogIntervalFrom(std::getenv("WATCHDOG_USEC"), std::getenv("WATCHDOG_PID"), static_cast<long>(::getpid()));
}

namespace {
Notifier& processNotifier() {
  static Notifier notifier = Notifier::fromEnvironment();
  return notifier;
}
}  // namespace

SendResult notifyReady() { return processNotifier().ready(); }
SendResult notifyWatchdog() { return processNotifier().watchdog(); }
SendResult notifyStopping() { return processNotifier().stopping(); }
SendResult notifyStatus(std::string_view text) { return processNotifier().status(text); }
SendResult notifyReadyWithStatus(std::string_view text) { return processNotifier().readyWithStatus(text); }

}  // namespace cyber::notify
