// The descriptor wrappers the daemon and cyber-plant-sim share (posix/include/cyber/posix/fd.hpp).

#include "cyber/posix/fd.hpp"

#include <gtest/gtest.h>

#include <time.h>
#include <unistd.h>

#include <cstdint>
#include <utility>

namespace cyber::posix {
namespace {

std::int64_t now() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

TEST(PosixFd, UniqueFdClosesOnceAndMovesOwnership) {
  int pipe_fds[2];
  ASSERT_EQ(::pipe(pipe_fds), 0);
  ::close(pipe_fds[1]);
  UniqueFd a(pipe_fds[0]);
  UniqueFd b(std::move(a));
  EXPECT_EQ(a.get(), -1);
  EXPECT_EQ(b.get(), pipe_fds[0]);
  const int released = b.release();
  EXPECT_EQ(b.get(), -1);
  EXPECT_EQ(::close(released), 0);  // still open: neither wrapper closed it
}

TEST(PosixFd, EpollReportsTheTagOfWhatIsReadable) {
  const Epoll poll;
  const EventFd wake;
  const TimerFd timer;
  poll.add(wake.fd(), 7);
  poll.add(timer.fd(), 9);
  wake.signal();
  std::uint64_t tags[4] = {};
  ASSERT_EQ(poll.wait(tags, 4), 1);
  EXPECT_EQ(tags[0], 7u);
  wake.drain();

  timer.startOnce(0);  // an absolute time in the past fires at once (0 itself would disarm)
  ASSERT_EQ(poll.wait(tags, 4), 1);
  EXPECT_EQ(tags[0], 9u);
  EXPECT_EQ(timer.consume(), 1u);
  EXPECT_EQ(timer.consume(), 0u);
}

TEST(PosixFd, PeriodicTimerCountsExpirationsAndStopDisarms) {
  const TimerFd timer;  // non-blocking: consume() returns 0 at once when nothing fired
  const TimerFd probe(true);
  const std::int64_t period = 1'000'000;
  timer.startPeriodic(now(), period);
  probe.startOnce(now() + 5 * period);
  probe.wait();
  EXPECT_GE(timer.consume(), 4u);
  timer.stop();
  timer.consume();
  probe.startOnce(now() + 5 * period);
  probe.wait();
  EXPECT_EQ(timer.consume(), 0u);  // nothing fired while stopped
}

}  // namespace
}  // namespace cyber::posix
