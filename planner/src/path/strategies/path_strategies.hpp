#pragma once
// The candidate paths of one move as an explicit, ordered list of strategies (docs/algorithm.md
// section 2.6). PathPlanner finds and smooths the first path (the straight segment when it is
// clear, else the search's); each strategy then may add candidates, fastest estimate first.
// A strategy is one file of this folder (named after it, defining path_strategies::<file name>)
// with its own gate, its own test and a one-line reason for being tried; the build lists every
// file here as a strategy (planner/CMakeLists.txt), so adding or removing one touches nothing
// else. Its thresholds are PathStrategySettings (planner_settings.hpp). This unit holds what the
// strategies share: their inputs, the candidate list, smoothing, and the registry.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "cyber/planner/chain.hpp"
#include "cyber/planner/collision_world.hpp"
#include "cyber/planner/robot_model.hpp"
#include "path/astar_search.hpp"
#include "path/cspace_grid.hpp"
#include "path/path_clearance.hpp"
#include "path/path_planner.hpp"

namespace cyber::planner {

// What every strategy reads: the move, and the first path as PathPlanner found it.
struct CandidateInputs {
  const RobotModel& model;
  const CollisionWorld& world;  // at the goal's scene offset, with the held pieces
  const CSpaceGrid& grid;       // of the held pieces
  DriveModel drives;            // with the held pieces
  JointVector start, goal, start_velocity;
  double b_start = 0.0;  // squared weighted start speed (path_timing.hpp)
  // The first path: start, the lead-in's end when there is one, the search's nodes, goal.
  std::vector<JointVector> polyline;
  int fixed_head = 1;  // polyline points every candidate keeps (start, and the lead-in's end)
  bool direct = false;
  // The search's cells, cost (its own metric) and connections; empty for a direct path.
  std::vector<int> first_cells;
  double first_cost = 0.0;
  std::vector<SearchEndpoint> source_links, goal_links;
  // straightEstimate from from() to the goal on timing_grid_points, for a searched first path
  // (what its detours are measured against); 0 for a direct one.
  double straight_estimate_s = 0.0;
  // The first path smoothed (path null when that failed): every other candidate starts as a copy.
  PlannedPath first;

  // Where the lead-in ends: the start when there is none.
  [[nodiscard]] const JointVector& from() const { return polyline[static_cast<size_t>(fixed_head - 1)]; }
  [[nodiscard]] const PathStrategySettings& settings() const { return model.planner.strategies; }
};

// The candidates so far, each with its reachability estimate on timing_grid_points (computed
// when first asked for).
class CandidateList {
 public:
  [[nodiscard]] bool empty() const { return paths_.empty(); }
  [[nodiscard]] size_t size() const { return paths_.size(); }
  [[nodiscard]] const PlannedPath& front() const { return paths_.front(); }
  [[nodiscard]] const std::vector<PlannedPath>& paths() const { return paths_; }
  std::vector<PlannedPath> release() { return std::move(paths_); }
  // The estimate of candidate i on the timing grid.
  [[nodiscard]] double estimate(const CandidateInputs& in, size_t i);
  // Inserted before the first candidate estimated slower.
  void addInTimeOrder(const CandidateInputs& in, PlannedPath path);
  void putFirst(PlannedPath path);
  // The clearance check of the last smoothing attempt: the reason when no candidate is left.
  ClearanceCheck last_check;
  // The strategy whose run adds candidates now: what each added one's PlanMethod names.
  std::string_view adding_for = PlanMethod::kFirstPath;

 private:
  std::vector<PlannedPath> paths_;
  std::vector<double> estimates_s_;  // NaN: not yet estimated
};

// Smooths `line` (which starts with the inputs' fixed head) into `into`: resample, optimise
// (eq. 8), spline, continuous check, weaker smoothing on failure (PlanMethod::Smoothing says which
// held). False when no attempt keeps the clearance and the limits (the last check is in `list`).
bool smoothPolyline(const CandidateInputs& in, const std::vector<JointVector>& line, PlannedPath& into,
                    CandidateList& list);

// The straight-segment estimate from rest (obstacles ignored), 0 between the same poses.
double straightEstimate(const JointVector& from, const JointVector& to, const DriveModel& drives,
                        const JointVector& metric, int grid_points);
// The larger of the joints' straightEstimate moving alone (the other staying at `from`).
double slowerJointAlone(const JointVector& from, const JointVector& to, const DriveModel& drives,
                        const JointVector& metric, int grid_points);

// `path` through `waypoints` put first, in `fastest`'s place, when an estimate on a finer grid than
// the searches' own confirms it faster (a coarse estimate can be fooled between its points).
// fastest_s: `fastest`'s estimate on that grid.
void putFirstIfFaster(const CandidateInputs& in, CandidateList& list, const PlannedPath& fastest, double fastest_s,
                      CubicSplinePath path, std::vector<JointVector> waypoints, double min_clearance_m,
                      PlanMethod::Smoothing smoothing);
// The shape search from `knots` (through which `fastest` runs), refined further when its shape
// is still estimated well above the slower joint moving alone; put first when faster.
void addShaped(const CandidateInputs& in, CandidateList& list, const PlannedPath& fastest,
               const std::vector<JointVector>& knots);
// The search's polyline with every run of nodes that a straight segment (clear by `clearance_m`)
// can replace replaced by it; the first fixed_head points are kept.
std::vector<JointVector> shortcutPolyline(const CollisionWorld& world, const std::vector<JointVector>& polyline,
                                          int fixed_head, double clearance_m);
// The clearance a shortcut keeps: the model's, with PathStrategySettings' margin.
double shortcutClearance(const CandidateInputs& in);
// `line` smoothed as a copy of the first path, added in the order of estimated time.
void addSmoothed(const CandidateInputs& in, CandidateList& list, const std::vector<JointVector>& line);

struct PathStrategy {
  std::string_view name;
  std::string_view reason;  // why it is tried
  int order = 0;            // strategies are tried in increasing order (docs/algorithm.md section 2.6)
  void (*run)(const CandidateInputs&, CandidateList&) = nullptr;
};

// Defines the strategy of a file of this folder: path_strategies::<the file's name>, which the
// build's list of the folder names (planner/CMakeLists.txt).
#define CYBER_PATH_STRATEGY(file_name, name, order, run, reason) \
  namespace path_strategies {                                    \
  extern const PathStrategy file_name;                           \
  }                                                              \
  const PathStrategy path_strategies::file_name { (name), (reason), (order), (run) }

// The strategies, in the order they are tried: every file of this folder, and any registered.
std::span<const PathStrategy> pathStrategies();

// The strategies of this folder's files, as the build lists them (in no particular order).
std::span<const PathStrategy* const> builtInPathStrategies();

// Adds a strategy made outside this folder (a test's) to pathStrategies(): a registration is a
// static object, made before the first call of pathStrategies() (later ones are not seen).
class PathStrategyRegistration {
 public:
  explicit PathStrategyRegistration(const PathStrategy& strategy);
};

}  // namespace cyber::planner
