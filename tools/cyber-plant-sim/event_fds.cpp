#include "event_fds.hpp"

#include <sys/epoll.h>
#include <sys/signalfd.h>
#include <sys/timerfd.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstring>
#include <ctime>

namespace cyber::plant {

namespace {

timespec toTimespec(double seconds) {
  timespec ts{};
  ts.tv_sec = static_cast<time_t>(std::floor(seconds));
  ts.tv_nsec = static_cast<long>(std::llround((seconds - std::floor(seconds)) * 1e9));
  if (ts.tv_nsec >= 1000000000L) {
    ++ts.tv_sec;
    ts.tv_nsec -= 1000000000L;
  }
  return ts;
}

std::string errnoText(const char* what) { return std::string(what) + ": " + std::strerror(errno); }

}  // namespace

double monotonicSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

std::int64_t realtimeMicros() {
  timespec ts{};
  clock_gettime(CLOCK_REALTIME, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000 + ts.tv_nsec / 1000;
}

OwnedFd& OwnedFd::operator=(OwnedFd&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = other.release();
  }
  return *this;
}

OwnedFd::~OwnedFd() {
  if (fd_ >= 0) ::close(fd_);
}

int OwnedFd::release() {
  const int fd = fd_;
  fd_ = -1;
  return fd;
}

MonotonicTimer MonotonicTimer::create(std::string& error) {
  MonotonicTimer timer;
  timer.fd_ = OwnedFd(timerfd_create(CLOCK_MONOTONIC, TFD_NONBLOCK | TFD_CLOEXEC));
  if (!timer.fd_.valid()) error = errnoText("timerfd_create");
  return timer;
}

bool MonotonicTimer::arm(double first_s, double period_s) {
  itimerspec spec{};
  spec.it_value = toTimespec(first_s);
  if (spec.it_value.tv_sec == 0 && spec.it_value.tv_nsec == 0) spec.it_value.tv_nsec = 1;  // 0 disarms
  spec.it_interval = toTimespec(period_s);
  return timerfd_settime(fd_.get(), TFD_TIMER_ABSTIME, &spec, nullptr) == 0;
}

bool MonotonicTimer::disarm() {
  itimerspec spec{};
  return timerfd_settime(fd_.get(), 0, &spec, nullptr) == 0;
}

std::uint64_t MonotonicTimer::consume() {
  std::uint64_t expirations = 0;
  if (::read(fd_.get(), &expirations, sizeof expirations) != sizeof expirations) return 0;
  return expirations;
}

OwnedFd makeStopSignalFd(std::string& error) {
  sigset_t mask;
  sigemptyset(&mask);
  sigaddset(&mask, SIGINT);
  sigaddset(&mask, SIGTERM);
  if (sigprocmask(SIG_BLOCK, &mask, nullptr) != 0) {
    error = errnoText("sigprocmask");
    return OwnedFd();
  }
  OwnedFd fd(signalfd(-1, &mask, SFD_NONBLOCK | SFD_CLOEXEC));
  if (!fd.valid()) error = errnoText("signalfd");
  return fd;
}

EventPoll EventPoll::create(std::string& error) {
  EventPoll poll;
  poll.fd_ = OwnedFd(epoll_create1(EPOLL_CLOEXEC));
  if (!poll.fd_.valid()) error = errnoText("epoll_create1");
  return poll;
}

bool EventPoll::add(int fd, std::uint64_t tag) {
  epoll_event event{};
  event.events = EPOLLIN;
  event.data.u64 = tag;
  return epoll_ctl(fd_.get(), EPOLL_CTL_ADD, fd, &event) == 0;
}

int EventPoll::wait(std::uint64_t* tags, int capacity) {
  epoll_event events[8];
  const int wanted = capacity < 8 ? capacity : 8;
  const int n = epoll_wait(fd_.get(), events, wanted, -1);
  for (int i = 0; i < n; ++i) tags[i] = events[i].data.u64;
  return n;
}

}  // namespace cyber::plant
