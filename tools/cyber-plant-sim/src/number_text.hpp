#pragma once
// Strict number parsing for command-line values: the whole text, finite, no locale.

#include <optional>
#include <string_view>
#include <vector>

namespace cyber::plant {

std::optional<double> parseNumber(std::string_view text);
// "A,B,..." with exactly `count` numbers.
std::optional<std::vector<double>> parseNumberList(std::string_view text, std::size_t count);

}  // namespace cyber::plant
