#pragma once
// Typed errors for every path a user can reach: a status and a human-readable reason.
// Exceptions are reserved for start-up configuration; the planner core returns these instead.

#include <string>
#include <string_view>
#include <utility>
#include <variant>

namespace cyber::planner {

enum class PlanStatus {
  kOk = 0,
  kInvalidInput,        // NaN/inf, malformed request, unknown scene
  kStartOutOfRange,     // start outside the joint limits
  kGoalOutOfRange,      // goal outside the joint limits
  kStartInCollision,    // start closer than the clearance
  kGoalInCollision,     // goal closer than the clearance
  kNoPath,              // the search found no collision-free path
  kClearanceNotMet,     // optimisation could not keep the clearance and no fallback did
  kInfeasibleStart,     // the start velocity cannot be followed and brought to rest
  kSolverNotConverged,  // TOPP did not meet its residual tolerances within its cap
  kInternalError,       // an invariant the planner checks itself failed
};

std::string_view toString(PlanStatus status);

// Exit code of a status for command-line tools (design.md): 2 bad input (malformed or non-finite),
// 3 no feasible motion (out of range, in collision, no path, solver did not converge).
int exitCodeOf(PlanStatus status);

struct PlanError {
  PlanStatus status = PlanStatus::kInternalError;
  std::string reason;
};

// A value or a PlanError. Small on purpose: has_value / value / error.
template <class T>
class Result {
 public:
  Result(T value) : storage_(std::move(value)) {}          // NOLINT(implicit)
  Result(PlanError error) : storage_(std::move(error)) {}  // NOLINT(implicit)
  static Result failure(PlanStatus status, std::string reason) { return Result(PlanError{status, std::move(reason)}); }

  [[nodiscard]] bool ok() const { return std::holds_alternative<T>(storage_); }
  explicit operator bool() const { return ok(); }
  [[nodiscard]] const T& value() const& { return std::get<T>(storage_); }
  [[nodiscard]] T& value() & { return std::get<T>(storage_); }
  [[nodiscard]] T&& value() && { return std::get<T>(std::move(storage_)); }
  [[nodiscard]] const PlanError& error() const { return std::get<PlanError>(storage_); }
  [[nodiscard]] PlanStatus status() const { return ok() ? PlanStatus::kOk : error().status; }

 private:
  std::variant<T, PlanError> storage_;
};

}  // namespace cyber::planner
