#pragma once
// The daemon's one event loop: epoll over file descriptors with a callback each, plus post() to
// run a function on the loop thread from any thread.

#include <functional>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <vector>

#include "cyber/daemon/io/fd.hpp"

namespace cyber::daemon::io {

class EventLoop {
 public:
  using Handler = std::function<void()>;

  EventLoop();
  EventLoop(const EventLoop&) = delete;
  EventLoop& operator=(const EventLoop&) = delete;

  // Calls `handler` on the loop thread whenever fd is readable (level-triggered).
  void add(int fd, Handler handler);
  void remove(int fd);
  [[nodiscard]] bool watching(int fd) const { return handlers_.count(fd) != 0; }

  // Runs until stop(); handlers run one at a time on this thread.
  void run();
  // Thread-safe.
  void stop();
  // Thread-safe: runs `task` on the loop thread soon.
  void post(Handler task);

 private:
  void runPosted();

  UniqueFd epoll_;
  EventFd wake_;
  std::unordered_map<int, std::shared_ptr<Handler>> handlers_;
  std::mutex posted_mutex_;
  std::vector<Handler> posted_;
  bool stopping_ = false;  // written via post, so only on the loop thread
};

}  // namespace cyber::daemon::io
