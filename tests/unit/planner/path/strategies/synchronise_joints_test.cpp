// The path strategy "synchronise the joints" (synchronise_joints.cpp) on the reference robot: on each move it was made
// for, the robot's fastest plan comes from it and beats the first path alone (docs/performance.md); where its gate is
// shut or it does not apply, it adds nothing (strategy_test_support.hpp).
#include "strategy_test_support.hpp"

namespace cyber::planner::test_strategies {
namespace {

const MadeFor kMadeFor[] = {
    {"synchronise the joints", "none:INTAKE->STOW", PlanMethod::Smoothing::kSynchronised, true},
    {"synchronise the joints", "coral:INTAKE->STOW", PlanMethod::Smoothing::kSynchronised, true},
};
INSTANTIATE_TEST_SUITE_P(Reference, StrategyMadeFor, ::testing::ValuesIn(kMadeFor));

const AddsNothing kAddsNothing[] = {
    {"SynchroniseOutsideItsWindow", "synchronise the joints", "none:INTAKE->STOW", true, JointVector::Zero(2)},
    {"SynchroniseFromAMovingStart", "synchronise the joints", "none:INTAKE->STOW", false, JointVector{{0.2, 0.0}}},
};
INSTANTIATE_TEST_SUITE_P(Reference, StrategyAddsNothing, ::testing::ValuesIn(kAddsNothing),
                         [](const ::testing::TestParamInfo<AddsNothing>& info) {
                           return std::string(info.param.name);
                         });

}  // namespace
}  // namespace cyber::planner::test_strategies
