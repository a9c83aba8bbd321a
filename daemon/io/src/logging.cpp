#include "cyber/daemon/io/logging.hpp"

#include <spdlog/async.h>
#include <spdlog/sinks/stdout_sinks.h>
#include <spdlog/spdlog.h>

#include "cyber/daemon/io/thread_priority.hpp"

namespace cyber::daemon::io {

bool setupLogging(const std::string& level) {
  const spdlog::level::level_enum parsed = spdlog::level::from_str(level);
  if (parsed == spdlog::level::off && level != "off") return false;
  spdlog::init_thread_pool(8192, 1, [] { useNormalScheduling(); });  // writes may block: never real-time
  // Overrun the oldest line rather than block a logging thread when the queue is full.
  auto logger = spdlog::create_async_nb<spdlog::sinks::stderr_sink_mt>("cyber-plannerd");
  logger->set_pattern("%Y-%m-%d %H:%M:%S.%e %l %v");
  logger->set_level(parsed);
  logger->flush_on(spdlog::level::warn);
  spdlog::set_default_logger(logger);
  return true;
}

void flushLogging() {
  if (auto logger = spdlog::default_logger()) logger->flush();
}

}  // namespace cyber::daemon::io
