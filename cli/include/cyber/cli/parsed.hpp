#pragma once
// The one way a program's command line comes back: its arguments, or the reason they are bad.

#include <string>
#include <utility>
#include <variant>

namespace cyber::cli {

// Every program exits with this status on a bad command line, after one line on stderr.
inline constexpr int kExitBadUsage = 2;

struct ArgumentError {
  std::string message;  // one line that names the offending argument
};

template <class T>
class Parsed {
 public:
  Parsed(T value) : v_(std::move(value)) {}
  Parsed(ArgumentError error) : v_(std::move(error)) {}
  [[nodiscard]] bool ok() const { return v_.index() == 0; }
  explicit operator bool() const { return ok(); }
  [[nodiscard]] const T& value() const { return std::get<0>(v_); }
  [[nodiscard]] T& value() { return std::get<0>(v_); }
  [[nodiscard]] const T* operator->() const { return &value(); }
  [[nodiscard]] const ArgumentError& error() const { return std::get<1>(v_); }

 private:
  std::variant<T, ArgumentError> v_;
};

}  // namespace cyber::cli
