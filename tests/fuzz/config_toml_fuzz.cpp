// Fuzz target: the input as the TOML robot description through parseConfig (the daemon's and the
// tools' loader, start-up only). Property: every invalid text is a ConfigError naming a key and
// saying what is wrong; no other exception, crash, hang or UB; a configuration that loads
// describes a usable robot (ordered joint ranges, a default scene, positive stream rate).

#include <cmath>
#include <string_view>

#include "cyber/config/load_config.hpp"
#include "fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 64 * 1024) return 0;  // a robot description is a few kB
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const cyber::config::Config config = cyber::config::parseConfig(text, "fuzz.toml");
    const auto& robot = config.robot;
    CYBER_FUZZ_CHECK(robot.range(0).min < robot.range(0).max);
    CYBER_FUZZ_CHECK(robot.range(1).min < robot.range(1).max);
    CYBER_FUZZ_CHECK(!robot.scenes.empty());
    CYBER_FUZZ_CHECK(std::isfinite(config.daemon.stream_rate_hz) && config.daemon.stream_rate_hz > 0.0);
  } catch (const cyber::config::ConfigError& error) {
    CYBER_FUZZ_CHECK(std::string_view(error.what()).find("fuzz.toml") == 0);
  }
  return 0;
}
