#pragma once
// The one way a program's command line comes back: cyber::Result<Arguments, ArgumentStatus>, its
// arguments or one line that names the offending argument.

#include <string>
#include <utility>

#include "cyber/result.hpp"

namespace cyber::cli {

// Every program exits with this status on a bad command line, after one line on stderr.
inline constexpr int kExitBadUsage = 2;

enum class ArgumentStatus { kOk, kBadUsage };

// A bad command line; `message` names the offending argument.
inline Error<ArgumentStatus> badUsage(std::string message) { return {ArgumentStatus::kBadUsage, std::move(message)}; }

}  // namespace cyber::cli
