// The path strategy "shape the fastest path" (shape_fastest_path.cpp) on the reference robot: on each move it was made
// for, the robot's fastest plan comes from it and beats the first path alone (docs/performance.md); where its gate is
// shut or it does not apply, it adds nothing (strategy_test_support.hpp).
#include "strategy_test_support.hpp"

namespace cyber::planner::test_strategies {
namespace {

const MadeFor kMadeFor[] = {
    {"shape the fastest path", "none:STOW->L4", PlanMethod::Smoothing::kShaped, true},
};
INSTANTIATE_TEST_SUITE_P(Reference, StrategyMadeFor, ::testing::ValuesIn(kMadeFor));

const AddsNothing kAddsNothing[] = {
    {"ShapeBelowItsRatio", "shape the fastest path", "none:STOW->L4", true, JointVector::Zero(2)},
};
INSTANTIATE_TEST_SUITE_P(Reference, StrategyAddsNothing, ::testing::ValuesIn(kAddsNothing),
                         [](const ::testing::TestParamInfo<AddsNothing>& info) {
                           return std::string(info.param.name);
                         });

}  // namespace
}  // namespace cyber::planner::test_strategies
