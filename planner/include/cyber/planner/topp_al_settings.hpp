#pragma once
// The settings of the augmented Lagrangian solver of docs/algorithm.md section 3 ("Stopping
// rules"). Its own header so ToppSettings (robot_model.hpp) holds them without the solver.

namespace cyber::planner::topp {

struct AlSettings {
  double primal_tolerance = 1e-6;
  double dual_tolerance = 1e-4;
  int max_outer_iterations = 50;  // a cap, never the stopping rule
  int max_inner_iterations = 500;
  double penalty_initial = 1e3;  // rho_0 of the augmented Lagrangian (cost scaled to order one)
  double penalty_growth = 1.0;   // gamma: rho <- min((1 + gamma) rho, beta)
  double penalty_max = 1e6;      // beta
  int lbfgs_memory = 8;
  int refresh_interval = 5;  // L-BFGS iterations before the preconditioner is refactored
};

}  // namespace cyber::planner::topp
