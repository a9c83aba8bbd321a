// The notify client against real AF_UNIX datagram sockets that the test binds itself, by path and
// by abstract name, as a service manager would.

#include "cyber/notify/notifier.hpp"

#include <gtest/gtest.h>

#include <sys/socket.h>
#include <sys/un.h>
#include <poll.h>
#include <unistd.h>
#include "allocation_counter.hpp"

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <new>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace {

using cyber::notify::Notifier;
using cyber::notify::SendResult;
using namespace std::chrono_literals;

std::string uniqueSuffix() {
  std::random_device device;
  return std::to_string(::getpid()) + "-" + std::to_string(device());
}

// A bound datagram socket playing the service manager.
class FakeManager {
 public:
  // abstract: bind "\0name" and give "@name" to the notifier; otherwise a path in a temp dir.
  explicit FakeManager(bool abstract) {
    fd_ = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    EXPECT_GE(fd_, 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    socklen_t length = 0;
    if (abstract) {
      const std::string name = "cyber-notify-test-" + uniqueSuffix();
      notify_socket_ = "@" + name;
      std::memcpy(address.sun_path + 1, name.data(), name.size());
      length = static_cast<socklen_t>(offsetof(sockaddr_un, sun_path) + 1 + name.size());
    } else {
      dir_ = std::filesystem::temp_directory_path() / ("cyber-notify-" + uniqueSuffix());
      std::filesystem::create_directories(dir_);
      notify_socket_ = (dir_ / "notify").string();
      std::memcpy(address.sun_path, notify_socket_.c_str(), notify_socket_.size() + 1);
      length = sizeof(address);
    }
    EXPECT_EQ(::bind(fd_, reinterpret_cast<sockaddr*>(&address), length), 0) << std::strerror(errno);
  }
  ~FakeManager() {
    ::close(fd_);
    if (!dir_.empty()) std::filesystem::remove_all(dir_);
  }
  FakeManager(const FakeManager&) = delete;
  FakeManager& operator=(const FakeManager&) = delete;

  const std::string& notifySocket() const { return notify_socket_; }

  // The next datagram, or nothing if none arrives within the timeout.
  std::optional<std::string> receive(std::chrono::milliseconds timeout = 2000ms) {
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(timeout.count())) != 1) return std::nullopt;
    char buffer[4096];
    const ssize_t n = ::recv(fd_, buffer, sizeof(buffer), 0);
    if (n < 0) return std::nullopt;
    return std::string(buffer, static_cast<std::size_t>(n));
  }

 private:
  int fd_ = -1;
  std::filesystem::path dir_;
  std::string notify_socket_;
};

class NotifierOnSocket : public ::testing::TestWithParam<bool> {};

TEST_P(NotifierOnSocket, SendsEachNotificationAsOneDatagram) {
  FakeManager manager(GetParam());
  Notifier notifier(manager.notifySocket());
  ASSERT_TRUE(notifier.enabled());

  EXPECT_EQ(notifier.ready(), SendResult::sent);
  EXPECT_EQ(manager.receive(), "READY=1");
  EXPECT_EQ(notifier.watchdog(), SendResult::sent);
  EXPECT_EQ(manager.receive(), "WATCHDOG=1");
  EXPECT_EQ(notifier.status("holding, 0 goals, CAN can0"), SendResult::sent);
  EXPECT_EQ(manager.receive(), "STATUS=holding, 0 goals, CAN can0");
  EXPECT_EQ(notifier.readyWithStatus("streaming"), SendResult::sent);
  EXPECT_EQ(manager.receive(), "READY=1\nSTATUS=streaming");
  EXPECT_EQ(notifier.stopping(), SendResult::sent);
  EXPECT_EQ(manager.receive(), "STOPPING=1");
  EXPECT_EQ(notifier.sendRaw("RELOADING=1"), SendResult::sent);
  EXPECT_EQ(manager.receive(), "RELOADING=1");
  EXPECT_EQ(manager.receive(100ms), std::nullopt);
}

INSTANTIATE_TEST_SUITE_P(PathAndAbstract, NotifierOnSocket, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "abstract" : "path"; });

TEST(Notifier, StatusKeepsOneLineAndIsCutAtTheLimit) {
  FakeManager manager(true);
  Notifier notifier(manager.notifySocket());
  EXPECT_EQ(notifier.status("line one\nline two\n"), SendResult::sent);
  EXPECT_EQ(manager.receive(), "STATUS=line one line two ");

  const std::string long_text(Notifier::kMaxStatusBytes + 50, 'x');
  EXPECT_EQ(notifier.status(long_text), SendResult::sent);
  EXPECT_EQ(manager.receive(), "STATUS=" + std::string(Notifier::kMaxStatusBytes, 'x'));

  EXPECT_EQ(notifier.status(""), SendResult::sent);
  EXPECT_EQ(manager.receive(), "STATUS=");
}

TEST(Notifier, BadSocketNamesGiveADisabledNotifier) {
  const std::string too_long_path = "/" + std::string(sizeof(sockaddr_un{}.sun_path), 'a');
  const std::string too_long_abstract = "@" + std::string(sizeof(sockaddr_un{}.sun_path), 'a');
  for (const std::string& name : {std::string(), std::string("relative/notify"), std::string("@"),
                                  std::string("vsock:2:1234"), too_long_path, too_long_abstract}) {
    Notifier notifier(name);
    EXPECT_FALSE(notifier.enabled()) << name;
    EXPECT_EQ(notifier.ready(), SendResult::disabled) << name;
    EXPECT_EQ(notifier.watchdog(), SendResult::disabled) << name;
    EXPECT_EQ(notifier.status("x"), SendResult::disabled) << name;
  }
  Notifier default_constructed;
  EXPECT_FALSE(default_constructed.enabled());
  EXPECT_EQ(default_constructed.stopping(), SendResult::disabled);
}

// `first` followed by `length` 'a's. (Built in place: g++ 12 at -O3 reports a false
// -Wrestrict inside "x" + std::string(...).)
std::string nameOfLength(char first, std::size_t length) {
  std::string name(length + 1, 'a');
  name[0] = first;
  return name;
}

TEST(Notifier, LongestPathThatFitsIsAccepted) {
  // sun_path is 108 bytes: a path of 107 characters plus its NUL fits, 108 does not.
  const std::size_t capacity = sizeof(sockaddr_un{}.sun_path);
  EXPECT_TRUE(Notifier(nameOfLength('/', capacity - 2)).enabled());
  EXPECT_FALSE(Notifier(nameOfLength('/', capacity - 1)).enabled());
  // An abstract name needs no NUL: '@' plus 107 characters fills sun_path exactly.
  EXPECT_TRUE(Notifier(nameOfLength('@', capacity - 1)).enabled());
}

TEST(Notifier, NobodyListeningIsAFailureNotAnException) {
  Notifier by_path("/nonexistent-dir-of-cyber-planner/notify");
  ASSERT_TRUE(by_path.enabled());
  EXPECT_EQ(by_path.ready(), SendResult::failed);
  Notifier abstract("@cyber-notify-nobody-" + uniqueSuffix());
  EXPECT_EQ(abstract.watchdog(), SendResult::failed);
}

TEST(Notifier, FullQueueFailsAtOnceInsteadOfBlocking) {
  FakeManager manager(false);
  Notifier notifier(manager.notifySocket());
  // The manager reads nothing: its queue fills up and sends must start failing, not block.
  int sent = 0;
  SendResult last = SendResult::sent;
  for (int i = 0; i < 100000 && last == SendResult::sent; ++i) {
    last = notifier.watchdog();
    if (last == SendResult::sent) ++sent;
  }
  EXPECT_EQ(last, SendResult::failed);
  EXPECT_GT(sent, 0);
  // What was queued is intact.
  EXPECT_EQ(manager.receive(), "WATCHDOG=1");
}

TEST(Notifier, WatchdogAndStatusDoNotAllocate) {
  FakeManager manager(true);
  Notifier notifier(manager.notifySocket());
  const std::string text = "moving request 42, 3 plans, 0 CAN errors";
  const long before = cyber::test::allocationCount();
  for (int i = 0; i < 10; ++i) {
    EXPECT_EQ(notifier.watchdog(), SendResult::sent);
  }
  EXPECT_EQ(notifier.status(text), SendResult::sent);
  const long after = cyber::test::allocationCount();
  EXPECT_EQ(after - before, 0);
  // The counter works: a string this long must allocate.
  std::string probe(100, 'p');
  EXPECT_GT(cyber::test::allocationCount(), after);
  EXPECT_EQ(manager.receive(), "WATCHDOG=1");
}

TEST(Notifier, MoveTransfersTheSocket) {
  FakeManager manager(true);
  Notifier first(manager.notifySocket());
  Notifier second(std::move(first));
  EXPECT_FALSE(first.enabled());  // NOLINT(bugprone-use-after-move): moved-from state is defined
  EXPECT_EQ(first.ready(), SendResult::disabled);
  EXPECT_EQ(second.ready(), SendResult::sent);
  EXPECT_EQ(manager.receive(), "READY=1");

  Notifier third;
  third = std::move(second);
  EXPECT_EQ(second.watchdog(), SendResult::disabled);
  EXPECT_EQ(third.watchdog(), SendResult::sent);
  EXPECT_EQ(manager.receive(), "WATCHDOG=1");
}

TEST(Notifier, ConcurrentSendersKeepDatagramsWhole) {
  FakeManager manager(false);
  Notifier notifier(manager.notifySocket());
  constexpr int kThreads = 4;
  constexpr int kPerThread = 50;
  std::atomic<int> sent{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      for (int i = 0; i < kPerThread; ++i) {
        const std::string text = "thread " + std::to_string(t) + " message " + std::to_string(i);
        // A full queue may refuse some; retry briefly, the reader below drains it.
        for (int attempt = 0; attempt < 1000; ++attempt) {
          if (notifier.status(text) == SendResult::sent) {
            sent.fetch_add(1);
            break;
          }
          std::this_thread::sleep_for(1ms);
        }
      }
    });
  }
  std::set<std::string> received;
  while (static_cast<int>(received.size()) < kThreads * kPerThread) {
    auto datagram = manager.receive();
    if (!datagram) break;
    received.insert(*datagram);
  }
  for (auto& thread : threads) thread.join();
  EXPECT_EQ(sent.load(), kThreads * kPerThread);
  ASSERT_EQ(static_cast<int>(received.size()), kThreads * kPerThread);
  for (int t = 0; t < kThreads; ++t) {
    for (int i = 0; i < kPerThread; ++i) {
      EXPECT_TRUE(received.count("STATUS=thread " + std::to_string(t) + " message " + std::to_string(i)));
    }
  }
}

TEST(Notifier, FromEnvironmentReadsNotifySocket) {
  FakeManager manager(true);
  ::unsetenv("NOTIFY_SOCKET");
  EXPECT_FALSE(Notifier::fromEnvironment().enabled());
  ::setenv("NOTIFY_SOCKET", manager.notifySocket().c_str(), 1);
  Notifier notifier = Notifier::fromEnvironment();
  ::unsetenv("NOTIFY_SOCKET");
  EXPECT_EQ(notifier.ready(), SendResult::sent);
  EXPECT_EQ(manager.receive(), "READY=1");
}

// The only test that uses the process-wide functions: the notifier is built from the
// environment on first use, so the variable is set before.
TEST(ProcessNotifier, FreeFunctionsUseNotifySocketAndDoNotAllocateAfterFirstUse) {
  FakeManager manager(false);
  ::setenv("NOTIFY_SOCKET", manager.notifySocket().c_str(), 1);
  EXPECT_EQ(cyber::notify::notifyStatus("starting"), SendResult::sent);
  EXPECT_EQ(manager.receive(), "STATUS=starting");
  const long before = cyber::test::allocationCount();
  EXPECT_EQ(cyber::notify::notifyWatchdog(), SendResult::sent);
  EXPECT_EQ(cyber::test::allocationCount(), before);
  EXPECT_EQ(manager.receive(), "WATCHDOG=1");
  EXPECT_EQ(cyber::notify::notifyReady(), SendResult::sent);
  EXPECT_EQ(manager.receive(), "READY=1");
  EXPECT_EQ(cyber::notify::notifyReadyWithStatus("up"), SendResult::sent);
  EXPECT_EQ(manager.receive(), "READY=1\nSTATUS=up");
  EXPECT_EQ(cyber::notify::notifyStopping(), SendResult::sent);
  EXPECT_EQ(manager.receive(), "STOPPING=1");
  ::unsetenv("NOTIFY_SOCKET");
}

TEST(WatchdogInterval, ParsesUsecAndHonoursPid) {
  using cyber::notify::watchdogIntervalFrom;
  EXPECT_EQ(watchdogIntervalFrom(nullptr, nullptr, 10), 0us);
  EXPECT_EQ(watchdogIntervalFrom("2000000", nullptr, 10), 2s);
  EXPECT_EQ(watchdogIntervalFrom("1", nullptr, 10), 1us);
  EXPECT_EQ(watchdogIntervalFrom("2000000", "10", 10), 2s);
  EXPECT_EQ(watchdogIntervalFrom("2000000", "11", 10), 0us);  // meant for another process
  EXPECT_EQ(watchdogIntervalFrom("2000000", "", 10), 0us);
  EXPECT_EQ(watchdogIntervalFrom("2000000", "ten", 10), 0us);
  for (const char* bad : {"", "0", "-5", "abc", "12abc", " 12", "99999999999999999999999"}) {
    EXPECT_EQ(watchdogIntervalFrom(bad, nullptr, 10), 0us) << bad;
  }
}

TEST(WatchdogInterval, ReadsTheEnvironment) {
  ::setenv("WATCHDOG_USEC", "500000", 1);
  ::unsetenv("WATCHDOG_PID");
  EXPECT_EQ(cyber::notify::watchdogInterval(), 500ms);
  ::setenv("WATCHDOG_PID", std::to_string(::getpid()).c_str(), 1);
  EXPECT_EQ(cyber::notify::watchdogInterval(), 500ms);
  ::setenv("WATCHDOG_PID", std::to_string(::getpid() + 1).c_str(), 1);
  EXPECT_EQ(cyber::notify::watchdogInterval(), 0us);
  ::unsetenv("WATCHDOG_PID");
  ::unsetenv("WATCHDOG_USEC");
  EXPECT_EQ(cyber::notify::watchdogInterval(), 0us);
}

TEST(SendResult, HasNames) {
  EXPECT_EQ(cyber::notify::toString(SendResult::sent), "sent");
  EXPECT_EQ(cyber::notify::toString(SendResult::disabled), "disabled");
  EXPECT_EQ(cyber::notify::toString(SendResult::failed), "failed");
}

}  // namespace
