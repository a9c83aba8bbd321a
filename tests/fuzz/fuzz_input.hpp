#pragma once
// Reading typed values off a fuzzer's input, front to back; past the end every read gives 0 (the
// same idea as clang's FuzzedDataProvider, which g++ builds of the replay tests do not have).

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace cyber::fuzz {

class FuzzInput {
 public:
  FuzzInput(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  template <class T>
  T take() {
    T value{};
    const std::size_t n = std::min(sizeof(T), size_ - at_);
    if (n > 0) std::memcpy(&value, data_ + at_, n);
    at_ += n;
    return value;
  }
  bool takeBool() { return (take<std::uint8_t>() & 1) != 0; }
  // The rest of the input.
  std::string_view rest() {
    const std::string_view out(reinterpret_cast<const char*>(data_ + at_), size_ - at_);
    at_ = size_;
    return out;
  }
  [[nodiscard]] std::size_t remaining() const { return size_ - at_; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t at_ = 0;
};

// The input cut at NUL bytes and newlines: how the command-line targets get their argv.
inline std::vector<std::string> splitArguments(std::string_view text) {
  std::vector<std::string> out;
  std::string current;
  for (const char c : text) {
    if (c == '\0' || c == '\n') {
      out.push_back(current);
      current.clear();
    } else {
      current += c;
    }
  }
  if (!current.empty()) out.push_back(current);
  return out;
}

}  // namespace cyber::fuzz
