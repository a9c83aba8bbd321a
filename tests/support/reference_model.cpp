#include "reference_model.hpp"

#include <cstdio>
#include <cstdlib>

#include "cyber/config/load_config.hpp"

namespace cyber::test {

const planner::RobotModel& referenceModel() {
  static const planner::RobotModel model = [] {
    try {
      return config::loadEmbeddedDefaultConfig().robot;
    } catch (const config::ConfigError& e) {
      std::fprintf(stderr, "embedded default configuration is invalid: %s\n", e.what());
      std::abort();
    }
  }();
  return model;
}

const planner::PathPlanner& referencePathPlanner() {
  static const planner::PathPlanner planner(referenceModel(), referenceModel().scenes.front());
  return planner;
}

planner::HeldPieces referencePieces(const std::string& names) {
  planner::HeldPieces held;
  if (names == "none") return held;
  std::string rest = names;
  while (!rest.empty()) {
    const size_t plus = rest.find('+');
    const std::string name = rest.substr(0, plus);
    const int index = referenceModel().pieceIndex(name);
    if (index < 0) {
      std::fprintf(stderr, "the reference robot has no game piece \"%s\"\n", name.c_str());
      std::abort();
    }
    held = held.with(index);
    rest = plus == std::string::npos ? std::string() : rest.substr(plus + 1);
  }
  return held;
}

}  // namespace cyber::test
