#pragma once
// The settings of the augmented Lagrangian solver of docs/algorithm.md section 3 ("Stopping
// rules"). Its own header so ToppSettings (robot_model.hpp) holds them without the solver.

#include <array>

#include "cyber/planner/types.hpp"

namespace cyber::planner::topp {

/// The augmented Lagrangian solver of TOPP (docs/algorithm.md section 3, "Stopping rules").
struct AlSettings {
  double primal_tolerance = 1e-6;
  double dual_tolerance = 1e-4;
  int max_outer_iterations = 50;  ///< a cap, never the stopping rule
  int max_inner_iterations = 500;
  double penalty_initial = 1e3;  ///< rho_0 of the augmented Lagrangian (cost scaled to order one)
  double penalty_growth = 1.0;   ///< gamma: rho <- min((1 + gamma) rho, beta)
  double penalty_max = 1e6;      ///< beta
  int lbfgs_memory = 8;
  int refresh_interval = 5;  ///< L-BFGS iterations before the preconditioner is refactored
  /// An outer step's inner solve stops at this share of the primal residual (as a relative dual
  /// residual), at most inner_target_cap and at least dual_tolerance: early outer steps need no
  /// more accuracy than their constraint violation, so they take few inner iterations.
  double inner_target_share = 0.1;
  double inner_target_cap = 1e-2;
};

}  // namespace cyber::planner::topp

/// Every tuned number of the planner, in one place (docs/algorithm.md section 6, "Settings"): the
/// rest is derived from the robot description. Each field says why it has its value; those
/// measured on the public moves say so. RobotModel::planner holds one PlannerSettings; the TOML's
/// [planner] table sets the grid, search, smoothing and TOPP parts, each key optional with these
/// values as its default (the three shipped robots' values), except the metric, the grid step and
/// the potential's range: a file that leaves those out gets them derived from its robot
/// (docs/configuration.md, "Defaults derived from the robot"); here they are the reference robot's.
namespace cyber::planner {

/// The configuration-space grid each held set is searched on (docs/algorithm.md section 2.1).
struct GridSettings {
  /// Cell size of each joint, joint units, one entry per joint (the loader derives it
  /// when the description leaves it out: one clearance of motion per step). MotionPlanner::create
  /// refuses a model whose step has not one entry per joint.
  JointVector step;
  /// Search nodes and optimised waypoints keep this far inside the joint limits [m or rad], so that
  /// a spline through them does not overshoot a limit it runs along (observed overshoots: <= 3 mm).
  double joint_limit_margin = 0.005;
};

/// The A* search over the grid and its potential field (docs/algorithm.md section 2.2).
struct SearchSettings {
  double potential_weight = 2.0;  ///< weight of the potential in the A* step cost
  /// Weighted C-space distance over which the potential decays (the loader's default: five
  /// clearances of motion).
  double potential_range = 0.15;
  /// Width of a band of scene offsets that shares one set of grids, in clearances: the grids of a
  /// band search the field elements swept across it, so a path may keep up to this much more than
  /// the clearance near them; narrower bands cost start-up time and memory (a set of grids per
  /// band; docs/algorithm.md section 2, "Scene offsets").
  double offset_band_clearances = 2.0;
};

/// Eq. 8 weights for waypoints waypoint_spacing apart (the terms are plain sums, so the balance
/// depends on the spacing). Tuned on the public moves: with w_p = 0.1, w_s = 10 the obstacle term
/// dragged waypoints out of the obstacles' channels and bunched them (then the spline cut corners
/// and fell back to the unsmoothed path), and L-BFGS needed ~40 iterations; these values keep the
/// search's topology, halve the curvature integral and converge in ~4 iterations.
struct SmoothingSettings {
  double waypoint_spacing = 0.05;     ///< weighted C-space spacing of the optimised waypoints
  double obstacle_weight = 0.5;       ///< w_o  (eq. 8)
  double obstacle_decay_m = 0.03;     ///< d0   (eq. 8)
  double prior_weight = 20.0;         ///< w_p
  double length_weight = 1.0;         ///< w_l
  double smoothness_weight = 1000.0;  ///< w_s
  int max_iterations = 200;
  double gradient_tolerance = 1e-6;
  /// L-BFGS also stops when a step lowers J by less than this fraction of max(1, |J|) (0: off).
  double relative_cost_tolerance = 1e-9;
  /// With a start velocity v0 the path first runs straight along v0 for |v0|_Sigma * lead_in_time_s
  /// (weighted length, at most max_lead_in), so a fast start does not meet a sharp bend at once.
  double lead_in_time_s = 0.1;
  double max_lead_in = 0.3;
  /// w_lim of the soft joint-limit term (path_optimizer.hpp): a stiffer one slows L-BFGS down a lot,
  /// and what this one leaves outside the margin is clamped.
  double joint_limit_weight = 100.0;
  /// When the smoothed path misses the clearance, smoothing is tried again with the obstacle weight
  /// multiplied by this, then the prior itself, then a prior with waypoints this share of
  /// waypoint_spacing apart (PlanMethod::Smoothing names the one that held).
  double retry_obstacle_factor = 10.0;
  double dense_prior_share = 0.25;
};

/// Time-optimal parameterisation: its grids, checks and solver (docs/algorithm.md section 3).
struct ToppSettings {
  int grid_points = 200;                 ///< K
  double limit_check_step_s = 0.001;     ///< the continuous trajectory is checked at this step
  double limit_check_tolerance = 0.005;  ///< relative overshoot of a limit accepted at that check
  int max_limit_refinements = 8;         ///< re-solves with tightened limits after a failed check
  /// Of limit_check_tolerance, the share accepted at the check's samples: the rest is left for
  /// the overshoot between them (a referee samples other instants).
  double check_share = 0.6;
  double max_margin = 0.05;    ///< limits are lowered by at most this fraction of themselves
  double refine_above = 0.02;  ///< overshoots beyond this fraction refine the grid instead
  int max_grid_factor = 8;     ///< the grid may grow to this multiple of grid_points
  /// After a failed check, a limit's margin grows by this multiple of its overshoot plus this share
  /// of the limit: the bulge between the grid points stays about the same when the limits at the
  /// ends move, so the excess and a little more bring the peak to the limit.
  double margin_overshoot = 1.1;
  double margin_floor = 1e-6;
  int timing_grid_points = 64;  ///< of the coarse grid whose profile places the real one's nodes
  /// Of the real grid, the share placed evenly in the coarse profile's time (the rest by the path's
  /// curvature): the slow ends of a rest-to-rest move, where the limits change fastest in time, get
  /// more points than a grid even in s gives them (docs/algorithm.md section 3, "Grid").
  double time_grid_share = 0.4;
  /// No cell counts more than this many times the mean time: the ends from rest would otherwise
  /// shrink the first intervals without bound (time ~ sqrt(s)) and the solver's conditioning with them.
  double max_time_density = 8.0;
  /// Tolerances, caps and penalty schedule of the solver; [planner.topp] sets all but the L-BFGS ones.
  topp::AlSettings solver;
};

/// The shape search (path_shaping.hpp).
struct ShapeSearchSettings {
  int bumps = 2;             ///< per joint
  int max_evaluations = 16;  ///< spline + reachability estimates
  int grid_points = 40;      ///< of each estimate
  /// Amplitude steps in joint units: the first joint's, and every later joint's. The first joint
  /// carries the whole chain, so the same step of it moves the robot furthest; measured on the
  /// public moves (about 10 ms of the reference robot's top speed each).
  double initial_step_first = 0.03;
  double initial_step_later = 0.09;
  double min_step_fraction = 0.125;  ///< stop when the steps have shrunk to this share
  /// A shape (here and in the refinement) is taken only when it is estimated at least this share
  /// faster: smaller gains are the estimate's noise.
  double min_gain = 1e-4;
};

/// The shape search's refinement (path_shaping.hpp): more bumps, each with its own step.
struct ShapeRefinementSettings {
  int bumps = 6;                                                         ///< per joint
  int max_evaluations = 100;                                             ///< spline + reachability estimates
  int grid_points = ShapeSearchSettings{}.grid_points;                   ///< of each estimate: the first search's,
  double initial_step_first = ShapeSearchSettings{}.initial_step_first;  ///< whose shape it goes on from
  double initial_step_later = ShapeSearchSettings{}.initial_step_later;  ///< whose shape it goes on from
  double min_step_fraction = 0.02;  ///< an amplitude whose step has shrunk to this share is done
  double max_step_fraction = 4.0;   ///< steps grow to at most this share
  double pin_width = 0.15;          ///< of the knots' arc fraction: the held window's half width (0: none)
};

/// The synchronised candidate (synchronised_path.hpp).
struct SynchronisedSettings {
  std::array<double, 3> slowdowns{1.0, 1.04, 1.1};  ///< of the slower joint's own profile
  int divisions = 4;                                ///< of the faster joint's stretch and of its delay, each
  int samples = 24;                                 ///< waypoints at even times, after the start
  int profile_points = 300;                         ///< of each joint's own profile
  int estimate_points = 40;                         ///< of each candidate's reachability estimate
  int max_estimates = 6;
  /// A candidate estimated within this factor of its construction's time is taken at once: its
  /// timing is (nearly) feasible, so no other pair of the same slowdown is much faster.
  double accept_ratio = 1.025;
};

/// When each path strategy is tried (path_strategies.hpp; docs/performance.md, "Choosing the path
/// for time"). The ratios compare reachability estimates of the same move, so they carry over from
/// robot to robot; the public moves tell where a strategy stops paying for its time.
struct PathStrategySettings {
  int timing_grid_points = 60;  ///< candidate paths are ordered by estimates on this many points
  /// Shortcut segments keep this many clearances more than the clearance, so smoothing has room at
  /// corners.
  double shortcut_margin_clearances = 0.5;
  /// The other way round is searched for when the best path takes this much longer than the straight
  /// segment would (obstacles ignored), with the first path's band this many nodes wide blocked.
  double detour_ratio = 1.05;
  int band_radius_nodes = 6;
  /// The other side of this many holes of C-space (the largest) is searched for as well, only when
  /// it costs at most this much more than the first path in the search's own metric (the other
  /// sides that were faster on the public moves cost 1.03-1.06 times as much; most that were not,
  /// 1.1 to 4.5 times): the search gives up early on a far detour, and it is not smoothed.
  int max_hole_sides = 2;
  double max_side_cost = 1.08;
  /// The fastest candidate's shape is searched against its estimated time when it is estimated this
  /// much slower than the straight segment, and kept when a finer estimate (check_grid_points) finds
  /// it this much faster: the search's own coarse estimate could be fooled between its grid points.
  double shape_ratio = 1.02;
  double shape_gain = 0.002;
  int check_grid_points = 100;
  /// The shape search goes on with its refinement when its shape is still estimated this much slower
  /// than the slower joint alone. On the public moves 53 pass (50 are refined: three are direct
  /// paths with too few knots); at 1.10 two moves stayed above 1.03 of the best known.
  double refine_ratio = 1.05;
  /// A direct path is shaped from this many knots along its straight segment, when its estimate (on
  /// gate_grid_points) is this much above its slower joint's alone: on the public moves those that
  /// gained were 1.006-1.06 above, the others equal (one joint's limits bind all along).
  int direct_shape_knots = 6;
  int gate_grid_points = 20;
  double direct_shape_ratio = 1.003;
  /// The synchronised candidate is tried when the slower joint alone is this much faster than the
  /// fastest candidate's estimate (check_grid_points): below that it cannot gain enough to matter.
  double synchronised_ratio = 1.01;
  /// Nor when it is this much slower: then the obstacles decide the move, and the joints' own
  /// motions side by side run into them (on the public moves the synchronised candidate was found
  /// only below 1.045; above, its profiles and clearance checks cost 1-2 ms for nothing).
  double synchronised_max_ratio = 1.08;
};

/// How MotionPlanner judges and repairs timed trajectories, and chooses between leaving along a
/// start velocity and stopping first (docs/moving-starts.md).
struct MotionSettings {
  /// Columns are judged at the samples of cyber-plan's CSV (docs/moving-starts.md), within 95 % of
  /// what an independent check of that CSV allows (1 % of the travel, 2 % of the peak speed).
  double consistency_step_s = 0.001;
  double max_position_error = 0.0095;
  double max_velocity_error = 0.019;
  /// After the fastest stop, the junction may be moved later by a multiple of this fraction of a
  /// step, up to gentler_steps of them, trying at most gentler_tries (each redoes the onward plan).
  double gentler_step = 0.125;
  int gentler_steps = 12;
  int gentler_tries = 6;
  /// When no gentler stop agrees, the onward plan from the fastest stop is slowed by up to this many
  /// slower_step (1.5 ms): within what a moving start may cost over stopping first
  /// (docs/moving-starts.md, "Consistent columns").
  int onward_slower_steps = 12;
  /// A rest-to-rest trajectory whose columns disagree is slowed down until its duration has grown by
  /// a multiple of this fraction of a step, up to slower_steps of them (two steps).
  double slower_step = 0.125;
  int slower_steps = 16;
  /// Beyond this duration a move has many acceleration jumps, spread in time, and a uniform slowdown
  /// of at most two steps moves each by a different fraction of a step; on the HIL tests' capped
  /// moves it never made one agree and cost up to 4.7 times the plan (docs/moving-starts.md,
  /// "Consistent columns").
  double slower_max_duration_s = 1.0;
  /// When no such slowdown agrees, the start is made gentler (gentlerStart) by this share of its
  /// first acceleration at a time, up to this many: an early switch moves by about the same share
  /// of its time (a whole step for a switch 10 ms in), for at most half that in duration.
  double gentler_start_step = 0.01;
  int gentler_start_steps = 25;
  /// A trajectory from rest is slowed or started more gently for its 1 ms columns only while its
  /// duration grows by at most this share: the plan is there to be fast, and its columns agree on
  /// finer samples anyway (cyber-plan then writes its CSV at such a spacing). Within 1 %, with the
  /// TOPP grid's 0.5 %, every plan stays within 1.02 of the fastest ride along its own path, as an
  /// independent referee judges it (docs/moving-starts.md, "Consistent columns").
  double max_consistency_cost = 0.01;
  /// A way out of the clearance (a few millimetres in tens of milliseconds) is slowed by up to this
  /// many slower_step: of clearance_escape_test's 58 ways out, 26 disagreed at 1 ms unslowed, 3 still
  /// did (6-7 % of the peak speed) after slower_steps, none after these (at most 8 ms more).
  int escape_slower_steps = 64;
  /// The reachability pass's estimate (path_timing.hpp, on this many points) is never below the
  /// optimiser's duration on the public moves and their splices, and at most this much above it:
  /// 10 % from a moving start, 2.5 % from rest (docs/moving-starts.md, "Planning time").
  int estimate_grid_points = 60;
  double moving_estimate_low = 0.85;
  double rest_estimate_low = 0.95;
  /// A path leaving along the start velocity whose tangent turns by more than a right angle
  /// (cosine below fold_cosine) between samples fold_samples_per_waypoint to a waypoint spacing
  /// folds back on itself: the mechanism must come to rest at the fold, as stopping first does
  /// with the fastest stop, and TOPP converges badly there (a one-joint random robot moving away
  /// from its goal: 2 s and 25 000 L-BFGS iterations for no plan). That candidate is timed only
  /// when stopping first has no plan (docs/moving-starts.md). A spline's corner of a right
  /// angle turns by a quarter of that per sample; a reversal, by half a turn.
  double fold_cosine = 0.0;
  int fold_samples_per_waypoint = 4;
};

/// The fastest stop along a start velocity (planner/src/motion/fastest_stop.hpp; docs/moving-starts.md):
/// the shortest line along v0 on which the start speed brakes to rest, found by bracketing and false
/// position on how much more than the start speed each line can stop from.
struct StopSettings {
  /// Grid of the first estimate from below of the braking distance (an outer bound on the
  /// deceleration): fine enough that the bracket around it rarely needs more than a step or two.
  int estimate_points = 200;
  /// The bracket widens around the estimate by this factor at a time, at most bracket_steps times
  /// each way: 1.2^12 (about 9) covers an estimate off by an order of magnitude.
  double bracket_growth = 1.2;
  int bracket_steps = 12;
  /// The line is at most this share longer than the shortest that stops: a stop 0.01 % longer than
  /// needed costs well under a microsecond.
  double length_tolerance = 1e-4;
  /// When neither the braking profile nor the optimiser's refined limits stop on that line, it is
  /// lengthened by this factor, at most max_retries times (1.002^8, 1.6 % longer, at worst).
  double retry_growth = 1.002;
  int max_retries = 8;
  /// The line never runs further than this (weighted C-space units) when no joint limit comes first:
  /// far beyond any stop of a mechanism that fits a robot, it only bounds the bracket.
  double max_length = 10.0;
};

/// The way out of the clearance from a start inside it (planner/src/path/clearance_escape.hpp).
struct EscapeSettings {
  /// How far past the clearance the escape ends [m], so that the plan from there starts clear of it.
  double margin_m = 0.002;
  /// The first line's length is the distance's first-order estimate; while its end falls short of
  /// the target distance it grows by this factor, at most length_tries times.
  double length_growth = 1.5;
  int length_tries = 8;
};

/// Every tuned number of the planner, each part with its reasons; RobotModel::planner holds one.
struct PlannerSettings {
  /// Diagonal of Sigma: |v|^2 = v' Sigma v, one entry per joint (the loader derives it
  /// when the description leaves it out: each joint weighted by the distance it moves the robot,
  /// the largest 1). MotionPlanner::create refuses a model whose metric has not one entry per joint.
  JointVector metric;
  GridSettings grid;
  SearchSettings search;
  SmoothingSettings smoothing;
  ToppSettings topp;
  PathStrategySettings strategies;
  ShapeSearchSettings shape_search;
  ShapeRefinementSettings shape_refinement;
  SynchronisedSettings synchronised;
  MotionSettings motion;
  StopSettings stop;
  EscapeSettings escape;
};

}  // namespace cyber::planner
