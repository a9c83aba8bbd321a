#pragma once
// A tolerance of floating-point arithmetic shared by the planner's step counts.

namespace cyber::planner {

// A quotient span / step within this of a whole number is that number: counting the steps of a
// span must not gain (ceil) or lose (floor) one to the roundoff of the division.
inline constexpr double kWholeCountSlack = 1e-9;

}  // namespace cyber::planner
