#include "number_text.hpp"

#include <charconv>
#include <cmath>

namespace cyber::plant {

std::optional<double> parseNumber(std::string_view text) {
  if (text.empty() || text.front() == '+') return std::nullopt;
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc{} || end != text.data() + text.size() || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

std::optional<std::vector<double>> parseNumberList(std::string_view text, std::size_t count) {
  std::vector<double> values;
  while (true) {
    const auto comma = text.find(',');
    const auto value = parseNumber(text.substr(0, comma));
    if (!value) return std::nullopt;
    values.push_back(*value);
    if (comma == std::string_view::npos) break;
    text.remove_prefix(comma + 1);
  }
  if (values.size() != count) return std::nullopt;
  return values;
}

}  // namespace cyber::plant
