#include <string>
#include <string_view>

#include "cyber/planner/motion_planner.hpp"

namespace cyber::planner {
namespace {

std::string_view smoothingName(PlanMethod::Smoothing smoothing) {
  switch (smoothing) {
    case PlanMethod::Smoothing::kStraight: return "straight";
    case PlanMethod::Smoothing::kOptimised: return "optimised";
    case PlanMethod::Smoothing::kStrongerObstacleWeight: return "optimised, stronger obstacle weight";
    case PlanMethod::Smoothing::kPrior: return "prior";
    case PlanMethod::Smoothing::kDensePrior: return "dense prior";
    case PlanMethod::Smoothing::kShaped: return "shaped for time";
    case PlanMethod::Smoothing::kSynchronised: return "synchronised";
    case PlanMethod::Smoothing::kStaying: return "zero-length";
  }
  return "unknown";
}

}  // namespace

std::string PlanMethod::name() const {
  std::string text;
  if (has(kStoppedFirst)) text += "stop, then ";
  if (has(kLeftTheClearance)) text += "out of the clearance, then ";
  text += strategy;
  text += " (";
  text += smoothingName(smoothing);
  if (!shaped_from.empty()) {
    text += " from ";
    text += shaped_from;
  }
  text += ")";
  if (has(kSlowedToAgree)) text += ", slowed to agree at 1 ms";
  if (has(kGentlerStart)) text += ", gentler start to agree at 1 ms";
  if (has(kSlowedAfterStop)) text += ", slowed to agree after the stop";
  return text;
}

}  // namespace cyber::planner
