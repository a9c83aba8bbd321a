// eq. 9
// eqs. 7-10
// algorithm.md section 3
// docs/design.md, "The gate"
// missing.hpp
// docs/missing.md
// cyberplanner/arm_state_t.hpp
