#include "cyber/cli/number_text.hpp"

#include <charconv>
#include <cmath>

namespace cyber::cli {

std::optional<double> parseNumber(std::string_view text, NonFinite non_finite) {
  if (text.empty() || text.front() == '+') return std::nullopt;
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc{} || end != text.data() + text.size()) return std::nullopt;
  if (non_finite == NonFinite::kReject && !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<std::int64_t> parseInteger(std::string_view text) {
  if (text.empty() || text.front() == '+') return std::nullopt;
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc{} || end != text.data() + text.size()) return std::nullopt;
  return value;
}

std::optional<std::array<double, 2>> parseNumberPair(std::string_view text, NonFinite non_finite) {
  const std::size_t comma = text.find(',');
  if (comma == std::string_view::npos) return std::nullopt;
  const auto a = parseNumber(text.substr(0, comma), non_finite);
  const auto b = parseNumber(text.substr(comma + 1), non_finite);  // a second comma fails here
  if (!a || !b) return std::nullopt;
  return std::array<double, 2>{*a, *b};
}

}  // namespace cyber::cli
