#pragma once
// Configuration-space vectors q = (q0, ..., q{N-1}): the N joints of the chain (1 <= N <= 3) in
// chain order, each in its own unit (m for a prismatic joint, rad for a revolute one;
// docs/algorithm.md section 1). N is read from the robot description, not compiled in: a
// JointVector carries its own size in a fixed capacity, so making one never allocates.

#include <array>
#include <cassert>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include <Eigen/Core>

#include "cyber/result.hpp"

namespace cyber::planner {

/// The most joints a chain may have: the grids and roadmaps of docs/algorithm.md section 2 grow
/// with the power of the joint count, and no FRC superstructure we know of has more than three.
inline constexpr int kMaxJoints = 3;

/// Joint positions (or their rates), chain order: N entries in a fixed capacity of kMaxJoints.
using JointVector = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxJoints, 1>;
/// An N x N matrix of the joints (a mass matrix), fixed capacity.
using JointMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, kMaxJoints, kMaxJoints>;
/// A 2 x N Jacobian: how a point of the side view moves per unit of each joint.
using PointJacobian = Eigen::Matrix<double, 2, Eigen::Dynamic, Eigen::ColMajor, 2, kMaxJoints>;
/// A 1 x N row: how one angle moves per unit of each joint.
using JointRow = Eigen::Matrix<double, 1, Eigen::Dynamic, Eigen::RowMajor, 1, kMaxJoints>;
using Point2 = Eigen::Vector2d;  ///< a point in the 2-D side view [m]

/// One value per joint, chain order, in a fixed capacity: copying one never allocates (unless T
/// does).
template <class T>
class PerJoint {
 public:
  PerJoint() = default;
  explicit PerJoint(int count, const T& value = T{}) : count_(count) {
    assert(count >= 0 && count <= kMaxJoints);
    for (int j = 0; j < count; ++j) items_[static_cast<size_t>(j)] = value;
  }
  PerJoint(std::initializer_list<T> items) : count_(static_cast<int>(items.size())) {
    assert(items.size() <= static_cast<size_t>(kMaxJoints));
    std::size_t j = 0;
    for (const T& item : items) items_[j++] = item;
  }

  [[nodiscard]] int size() const { return count_; }
  [[nodiscard]] bool empty() const { return count_ == 0; }
  T& operator[](int j) { return items_[static_cast<size_t>(j)]; }
  const T& operator[](int j) const { return items_[static_cast<size_t>(j)]; }
  T& operator[](size_t j) { return items_[j]; }
  const T& operator[](size_t j) const { return items_[j]; }
  T& front() { return items_[0]; }
  const T& front() const { return items_[0]; }
  T& back() { return items_[static_cast<size_t>(count_ - 1)]; }
  const T& back() const { return items_[static_cast<size_t>(count_ - 1)]; }
  void push_back(const T& item) {
    assert(count_ < kMaxJoints);
    items_[static_cast<size_t>(count_++)] = item;
  }
  void resize(int count) {
    assert(count >= 0 && count <= kMaxJoints);
    count_ = count;
  }
  T* begin() { return items_.data(); }
  T* end() { return items_.data() + count_; }
  const T* begin() const { return items_.data(); }
  const T* end() const { return items_.data() + count_; }

 private:
  std::array<T, kMaxJoints> items_{};
  int count_ = 0;
};

/// The game pieces held, as a set of indices into RobotModel::pieces. Each held piece adds
/// polygons; none removes any.
struct HeldPieces {
  std::uint32_t bits = 0;

  /// The grids and collision worlds are made for every set at start-up (docs/algorithm.md
  /// section 2), so the number of named pieces is bounded.
  static constexpr int kMaxPieces = 4;

  [[nodiscard]] bool holds(int piece) const { return ((bits >> piece) & 1U) != 0; }
  [[nodiscard]] HeldPieces with(int piece) const { return HeldPieces{bits | (1U << piece)}; }
  [[nodiscard]] bool empty() const { return bits == 0; }
  /// Index of the per-piece-set grids and worlds: 0 .. setCount(pieces) - 1.
  [[nodiscard]] int index() const { return static_cast<int>(bits); }
  static HeldPieces fromIndex(int i) { return HeldPieces{static_cast<std::uint32_t>(i)}; }
  /// How many sets `piece_count` named pieces make.
  static constexpr int setCount(int piece_count) { return 1 << piece_count; }
  friend bool operator==(const HeldPieces&, const HeldPieces&) = default;
};

/// Typed errors for every path a user can reach: a status and a human-readable reason.
/// Exceptions are reserved for start-up configuration; the planner core returns these instead.

/// Why a plan (or any planner call) failed; kOk for success.
enum class PlanStatus {
  kOk = 0,
  kInvalidInput,        ///< NaN/inf, malformed request, unknown scene
  kStartOutOfRange,     ///< start outside the joint limits
  kGoalOutOfRange,      ///< goal outside the joint limits
  kStartInCollision,    ///< start closer than the clearance
  kGoalInCollision,     ///< goal closer than the clearance
  kNoPath,              ///< the search found no collision-free path
  kClearanceNotMet,     ///< optimisation could not keep the clearance and no fallback did
  kInfeasibleStart,     ///< the start velocity cannot be followed and brought to rest
  kSolverNotConverged,  ///< TOPP did not meet its residual tolerances within its cap
  kInternalError,       ///< an invariant the planner checks itself failed
  /// The timed trajectory's velocity or acceleration columns do not integrate to the columns above
  /// them at the consumer's 1 ms (docs/moving-starts.md, "Consistent columns"), and no slower or
  /// gentler variant of the plan made them agree.
  kColumnsDisagree,
};

/// The status as a few words for a person.
std::string_view toString(PlanStatus status);

/// Exit code of a status for command-line tools (design.md): 2 bad input (malformed or non-finite),
/// 3 no feasible motion (out of range, in collision, no path, solver did not converge, columns
/// that disagree).
int exitCodeOf(PlanStatus status);

/// What went wrong: a PlanStatus and a message for a person (cyber/result.hpp).
using PlanError = cyber::Error<PlanStatus>;

/// A value or a PlanError: ok() / value() / error() / status() (cyber/result.hpp).
template <class T>
using Result = cyber::Result<T, PlanStatus>;

/// A geometric path q(s), s in [0, length]: what the path stage produces and TOPP consumes.
/// s is the weighted arc length of algorithm.md section 2.4 for splines; TOPP only needs q, q', q''.

/// A point of a geometric path with its first and second derivatives in s.
struct PathPoint {
  JointVector q;
  JointVector dq_ds;    ///< q'(s)
  JointVector d2q_ds2;  ///< q''(s)
};

/// A geometric path q(s), s in [0, length]: what the path stage produces and TOPP consumes.
class GeometricPath {
 public:
  virtual ~GeometricPath() = default;
  [[nodiscard]] virtual double length() const = 0;
  /// s is clamped to [0, length()]. Must not allocate (the streamer samples through it).
  [[nodiscard]] virtual PathPoint at(double s) const = 0;
};

/// A convex polygon with counter-clockwise vertices, validated on construction.

/// A convex polygon, counter-clockwise: the outline of a link, a piece or an obstacle.
class ConvexPolygon {
 public:
  ConvexPolygon() = default;

  /// Accepts either orientation and stores counter-clockwise. kInvalidInput, with the reason, when
  /// the vertices are fewer than 3, non-finite, collinear or not convex.
  static Result<ConvexPolygon> fromVertices(std::vector<Point2> vertices);

  /// Everything the polygon covers while it slides along x from lo_m to hi_m (lo_m <= hi_m): the
  /// convex hull of its two end copies (a Minkowski sum with a segment). For lo_m == hi_m, the
  /// polygon moved by lo_m.
  [[nodiscard]] ConvexPolygon sweptAlongX(double lo_m, double hi_m) const;

  [[nodiscard]] const std::vector<Point2>& vertices() const { return vertices_; }
  [[nodiscard]] int size() const { return static_cast<int>(vertices_.size()); }
  [[nodiscard]] bool empty() const { return vertices_.empty(); }
  [[nodiscard]] const Point2& vertex(int i) const { return vertices_[static_cast<size_t>(i)]; }
  /// Edge i runs from vertex(i) to vertex(i+1 mod n).
  [[nodiscard]] const Point2& edgeEnd(int i) const { return vertices_[static_cast<size_t>((i + 1) % size())]; }

 private:
  explicit ConvexPolygon(std::vector<Point2> ccw) : vertices_(std::move(ccw)) {}
  std::vector<Point2> vertices_;
};

}  // namespace cyber::planner
