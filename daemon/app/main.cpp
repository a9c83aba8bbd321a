// cyber-plannerd: the motion-planning daemon (docs/operations.md).
//   cyber-plannerd [--config FILE] [--can IFACE|none] [--lcm-url URL]
// Exit codes: 0 stopped by SIGTERM/SIGINT, 2 bad command line or configuration, 1 any other
// start-up failure (LCM, CAN interface, planner set-up). Each failure is one line on stderr.

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <spdlog/spdlog.h>

#include "cyber/cli/usage_exit.hpp"
#include "cyber/config/load_config.hpp"
#include "cyber/daemon/io/command_line.hpp"
#include "cyber/daemon/io/daemon.hpp"
#include "cyber/daemon/io/fd.hpp"
#include "cyber/daemon/io/logging.hpp"
#include "cyber/daemon/io/process_signals.hpp"
#include "cyber/daemon/motion_planner_service.hpp"

namespace {

int fail(int code, const std::string& message) {
  std::cerr << "cyber-plannerd: " << message << "\n";
  return code;
}

// The grid cache's folder: systemd's CacheDirectory= (the unit's CacheDirectory=cyber-planner sets
// $CACHE_DIRECTORY, the first of a ':'-separated list); none when started without it.
std::optional<std::filesystem::path> gridCacheDir() {
  const char* dirs = std::getenv("CACHE_DIRECTORY");
  if (dirs == nullptr) return std::nullopt;
  const std::string first = std::string(dirs).substr(0, std::string(dirs).find(':'));
  if (first.empty()) return std::nullopt;
  return std::filesystem::path(first);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace cyber;
  const auto parsed = daemon::io::parseCommandLine(std::vector<std::string>(argv + 1, argv + argc));
  if (const auto status = cli::exitBeforeWork(parsed, {"cyber-plannerd", daemon::io::usage(), true})) return *status;
  const auto& command = parsed.value();

  // Before any thread exists, so every thread inherits the blocked mask and the signals arrive
  // only through this descriptor.
  daemon::io::SignalFd signals({SIGTERM, SIGINT});
  daemon::io::ignoreHangupAndPipe();

  config::Config config;
  try {
    // Without --config, the embedded reference robot, as cyber-plan does.
    config =
        command.config_path.empty() ? config::loadEmbeddedDefaultConfig() : config::loadConfigFile(command.config_path);
  } catch (const config::ConfigError& error) {
    return fail(2, error.what());
  }
  daemon::io::DaemonOptions options;
  options.settings = config.daemon;
  options.poses = config.poses;
  if (command.lcm_url) options.settings.lcm_url = *command.lcm_url;
  if (command.can_interface) {
    if (*command.can_interface == "none") {
      options.simulate_can = true;
    } else {
      options.settings.can_interface = *command.can_interface;
    }
  }
  if (!daemon::io::setupLogging(options.settings.log_level)) {
    return fail(2, "log_level '" + options.settings.log_level + "' is not a spdlog level");
  }

  const std::optional<std::filesystem::path> cache_dir = gridCacheDir();
  const auto planner_start = std::chrono::steady_clock::now();
  auto planning = daemon::makeMotionPlannerService(config.robot, cache_dir);
  if (!planning) return fail(1, "planner set-up failed: " + planning.error().message);
  const double planner_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - planner_start).count();
  try {
    daemon::io::Daemon daemon(config.robot, options, *planning.value(), &signals);
    // What a restart waits for (docs/performance.md, "Start-up"), and whether it could keep its
    // grids; once CAN and LCM are open, so that a start-up error stays the one line it prints.
    spdlog::info("planner ready in {:.0f} ms, grid cache {}", planner_ms,
                 cache_dir ? cache_dir->string() : std::string("off (no $CACHE_DIRECTORY)"));
    return daemon.run();
  } catch (const daemon::io::StartupError& error) {
    daemon::io::flushLogging();
    return fail(1, error.what());
  } catch (const std::exception& error) {
    daemon::io::flushLogging();
    return fail(1, std::string("start-up failed: ") + error.what());
  }
}
