#pragma once
// Helpers for the tools' command-line tests: the value of a line that must parse, the message
// of one that must not.

#include <gtest/gtest.h>

#include <string>
#include <type_traits>
#include <vector>

#include "cyber/cli/argument_status.hpp"

namespace cyber::tools {

template <class Parse>
auto parsedOk(Parse parse, const std::vector<std::string>& args) {
  const auto parsed = parse(args);
  using Arguments = std::decay_t<decltype(parsed.value())>;
  EXPECT_TRUE(parsed.ok()) << (parsed.ok() ? "" : parsed.error().message);
  return parsed.ok() ? parsed.value() : Arguments{};
}

template <class Parse>
std::string parseError(Parse parse, const std::vector<std::string>& args) {
  const auto parsed = parse(args);
  EXPECT_EQ(parsed.status(), cli::ArgumentStatus::kBadUsage);
  return parsed.ok() ? "" : parsed.error().message;
}

}  // namespace cyber::tools
