#include "cyber/posix/fd.hpp"

#include <sys/epoll.h>
#include <sys/eventfd.h>
#include <sys/signalfd.h>
#include <sys/timerfd.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>
#include <pthread.h>

namespace cyber::posix {

namespace {

[[noreturn]] void fail(const char* what) { throw std::system_error(errno, std::generic_category(), what); }

// An absolute time of 0 would disarm the timer: 1 ns is as much in the past.
timespec toExpiry(std::int64_t ns) {
  timespec ts{};
  if (ns <= 0) {
    ts.tv_nsec = 1;
    return ts;
  }
  ts.tv_sec = static_cast<time_t>(ns / 1'000'000'000);
  ts.tv_nsec = static_cast<long>(ns % 1'000'000'000);
  return ts;
}

timespec toTimespec(std::int64_t ns) {
  timespec ts{};
  ts.tv_sec = static_cast<time_t>(ns / 1'000'000'000);
  ts.tv_nsec = static_cast<long>(ns % 1'000'000'000);
  return ts;
}

}  // namespace

UniqueFd& UniqueFd::operator=(UniqueFd&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = other.release();
  }
  return *this;
}

UniqueFd::~UniqueFd() {
  if (fd_ >= 0) ::close(fd_);
}

EventFd::EventFd() : fd_(::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC)) {
  if (fd_.get() < 0) fail("eventfd");
}

void EventFd::signal() const {
  const std::uint64_t one = 1;
  // Non-blocking: fails only if the counter would overflow, and then the loop is woken anyway.
  [[maybe_unused]] const ssize_t n = ::write(fd_.get(), &one, sizeof one);
}

void EventFd::drain() const {
  std::uint64_t count = 0;
  [[maybe_unused]] const ssize_t n = ::read(fd_.get(), &count, sizeof count);
}

TimerFd::TimerFd(bool blocking) : fd_(::timerfd_create(CLOCK_MONOTONIC, TFD_CLOEXEC | (blocking ? 0 : TFD_NONBLOCK))) {
  if (fd_.get() < 0) fail("timerfd_create");
}

void TimerFd::startPeriodic(std::int64_t first_ns, std::int64_t period_ns) const {
  itimerspec spec{};
  spec.it_value = toExpiry(first_ns);
  spec.it_interval = toTimespec(period_ns);
  if (::timerfd_settime(fd_.get(), TFD_TIMER_ABSTIME, &spec, nullptr) != 0) fail("timerfd_settime");
}

void TimerFd::startOnce(std::int64_t at_ns) const {
  itimerspec spec{};
  spec.it_value = toExpiry(at_ns);
  if (::timerfd_settime(fd_.get(), TFD_TIMER_ABSTIME, &spec, nullptr) != 0) fail("timerfd_settime");
}

void TimerFd::stop() const {
  itimerspec spec{};
  if (::timerfd_settime(fd_.get(), 0, &spec, nullptr) != 0) fail("timerfd_settime");
}

std::uint64_t TimerFd::wait() const {
  for (;;) {
    std::uint64_t expirations = 0;
    const ssize_t n = ::read(fd_.get(), &expirations, sizeof expirations);
    if (n == sizeof expirations) return expirations;
    if (n < 0 && errno == EINTR) continue;
    return 0;
  }
}

std::uint64_t TimerFd::consume() const {
  std::uint64_t expirations = 0;
  return ::read(fd_.get(), &expirations, sizeof expirations) == sizeof expirations ? expirations : 0;
}

SignalFd::SignalFd(std::initializer_list<int> signals) {
  sigset_t set;
  sigemptyset(&set);
  for (int s : signals) sigaddset(&set, s);
  if (pthread_sigmask(SIG_BLOCK, &set, nullptr) != 0) fail("pthread_sigmask");
  fd_ = UniqueFd(::signalfd(-1, &set, SFD_NONBLOCK | SFD_CLOEXEC));
  if (fd_.get() < 0) fail("signalfd");
}

int SignalFd::take() const {
  signalfd_siginfo info{};
  return ::read(fd_.get(), &info, sizeof info) == sizeof info ? static_cast<int>(info.ssi_signo) : 0;
}

Epoll::Epoll() : fd_(::epoll_create1(EPOLL_CLOEXEC)) {
  if (fd_.get() < 0) fail("epoll_create1");
}

void Epoll::add(int fd, std::uint64_t tag) const {
  epoll_event event{};
  event.events = EPOLLIN;
  event.data.u64 = tag;
  if (::epoll_ctl(fd_.get(), EPOLL_CTL_ADD, fd, &event) != 0) fail("epoll_ctl");
}

int Epoll::wait(std::uint64_t* tags, int capacity) const {
  constexpr int kBatch = 8;
  epoll_event events[kBatch];
  const int n = ::epoll_wait(fd_.get(), events, capacity < kBatch ? capacity : kBatch, -1);
  if (n < 0) return errno == EINTR ? 0 : -1;
  for (int i = 0; i < n; ++i) tags[i] = events[i].data.u64;
  return n;
}

}  // namespace cyber::posix
