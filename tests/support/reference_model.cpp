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
  const auto held = referenceModel().piecesNamed(names);
  if (!held) {
    std::fprintf(stderr, "%s\n", held.error().message.c_str());
    std::abort();
  }
  return held.value();
}

}  // namespace cyber::test
