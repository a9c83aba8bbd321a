#pragma once
// Strict numbers for command-line values: the whole text, no locale, no leading '+' or blanks.

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace cyber::cli {

enum class NonFinite { kReject, kAccept };

std::optional<double> parseNumber(std::string_view text, NonFinite non_finite = NonFinite::kReject);
std::optional<std::int64_t> parseInteger(std::string_view text);
// "A,B": exactly two numbers separated by one comma.
std::optional<std::array<double, 2>> parseNumberPair(std::string_view text, NonFinite non_finite = NonFinite::kReject);

}  // namespace cyber::cli
