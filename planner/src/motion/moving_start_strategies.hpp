#pragma once
// The candidates of a moving start as an explicit, ordered list of strategies
// (docs/moving-starts.md). Each strategy runs its path stage and says what its candidate is
// estimated to take, and how fast it could be at best; the chooser times a candidate only while
// it can still win, and streams the one whose columns agree, fastest first. A strategy is one
// function with its own test and a one-line reason; its thresholds are MotionSettings
// (planner_settings.hpp).

#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <string_view>

#include "cyber/planner/motion_planner.hpp"
#include "cyber/planner/robot_model.hpp"
#include "path/path_planner.hpp"

namespace cyber::planner {

struct MovingStartInputs {
  const RobotModel& model;
  const PathPlanner& paths;  // at the request's scene offset
  const PlanRequest& request;
};

// A strategy's candidate once its path stage has run.
struct MovingStartCandidate {
  std::optional<PlanError> refused;                             // why it has no candidate; then it is never timed
  double estimate_s = std::numeric_limits<double>::infinity();  // the reachability estimate
  double lower_bound_s = 0.0;                                   // its timed duration is not expected below this
  std::function<Result<Plan>()> time;                           // TOPP, and the adjustments that make its columns agree
};

struct MovingStartStrategy {
  std::string_view name;    // how a refusal names it
  std::string_view reason;  // why it is tried
  MovingStartCandidate (*prepare)(const MovingStartInputs&);
};

// The strategies, in the order they are tried.
std::span<const MovingStartStrategy> movingStartStrategies();

// Each strategy on its own (the list's entries), for tests.
MovingStartCandidate leaveAlongVelocity(const MovingStartInputs& in);
MovingStartCandidate stopFirst(const MovingStartInputs& in);

// Prepares every strategy in order (an error of the request itself, the same for all, is returned
// at once); times each candidate, in order, whose lower bound is not above the best any other
// promises (its timed duration when its columns agree, its estimate before it is timed); when none
// timed agrees, times the ones left out. The plan: columns agreeing first, then the shortest,
// earlier strategies winning ties. When none serves, the first one's reason, then each other's
// after "; NAME: ".
Result<Plan> planMovingStart(const MovingStartInputs& in, std::span<const MovingStartStrategy> strategies);

}  // namespace cyber::planner
