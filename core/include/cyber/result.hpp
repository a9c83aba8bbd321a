#pragma once
// The one way a fallible call returns, in every component (planner, can, cli, the tools): a value,
// or an error made of a status from the component's own enum and a message for a person
// (docs/design.md, "Conventions"). No exceptions past start-up, no out-parameters. Copying an
// error's status allocates nothing, and an empty message allocates nothing either, so the CAN
// codecs return it on the streaming path (their errors carry a status only).

#include <string>
#include <type_traits>
#include <utility>
#include <variant>

namespace cyber {

// What went wrong: a status of the component's enum (never its kOk) and a message for a person.
template <class Status>
struct Error {
  Status status{};
  std::string message;
};

// A T, or an Error<Status>. Status is an enum class of the component whose first value, kOk, is
// what status() says of a value.
template <class T, class Status>
class [[nodiscard]] Result {
 public:
  Result(T value) : storage_(std::in_place_index<0>, std::move(value)) {}                 // NOLINT(implicit)
  Result(Error<Status> error) : storage_(std::in_place_index<1>, std::move(error)) {}     // NOLINT(implicit)
  Result(Status status) : storage_(std::in_place_index<1>, Error<Status>{status, {}}) {}  // NOLINT(implicit)
  static Result failure(Status status, std::string message) {
    return Result(Error<Status>{status, std::move(message)});
  }

  [[nodiscard]] bool ok() const { return storage_.index() == 0; }
  explicit operator bool() const { return ok(); }
  [[nodiscard]] const T& value() const& { return std::get<0>(storage_); }
  [[nodiscard]] T& value() & { return std::get<0>(storage_); }
  [[nodiscard]] T&& value() && { return std::get<0>(std::move(storage_)); }
  [[nodiscard]] const T* operator->() const { return &value(); }
  [[nodiscard]] T* operator->() { return &value(); }
  [[nodiscard]] const Error<Status>& error() const { return std::get<1>(storage_); }
  [[nodiscard]] Status status() const { return ok() ? Status{} : error().status; }

 private:
  std::variant<T, Error<Status>> storage_;
};

// Success without a value (a file written, a check passed).
struct Done {};

}  // namespace cyber
