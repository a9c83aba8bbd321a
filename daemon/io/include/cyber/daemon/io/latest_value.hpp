#pragma once
// The latest value of a small trivially copyable struct, written by one thread and read by
// others without locks (a sequence lock over atomic words, so it is race-free in the C++ memory
// model). The writer never waits. load() retries while a write is in progress; tryLoad() makes one
// attempt, for a reader that must not wait for the writer (docs/design.md, "Threads and
// ownership"): on one CPU, a reader of higher real-time priority that preempted the writer in the
// middle of a store would spin in load() for ever, since the writer cannot run to finish it.

#include <array>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <optional>
#include <type_traits>

namespace cyber::daemon::io {

template <class T>
class LatestValue {
  static_assert(std::is_trivially_copyable_v<T>, "LatestValue holds trivially copyable values");
  static constexpr std::size_t kWords = (sizeof(T) + sizeof(std::uint64_t) - 1) / sizeof(std::uint64_t);

 public:
  explicit LatestValue(const T& initial = T{}) { store(initial); }

  void store(const T& value) {
    std::array<std::uint64_t, kWords> words{};
    std::memcpy(words.data(), &value, sizeof(T));
    const std::uint64_t seq = sequence_.load(std::memory_order_relaxed);
    sequence_.store(seq + 1, std::memory_order_relaxed);
    std::atomic_thread_fence(std::memory_order_release);
    for (std::size_t i = 0; i < kWords; ++i) words_[i].store(words[i], std::memory_order_relaxed);
    sequence_.store(seq + 2, std::memory_order_release);
  }

  [[nodiscard]] T load() const {
    for (;;) {
      if (const std::optional<T> value = tryLoad()) return *value;
    }
  }

  // The value, or nothing when a write is in progress or ended while it was being read.
  [[nodiscard]] std::optional<T> tryLoad() const {
    std::array<std::uint64_t, kWords> words{};
    const std::uint64_t before = sequence_.load(std::memory_order_acquire);
    if ((before & 1) != 0) return std::nullopt;
    for (std::size_t i = 0; i < kWords; ++i) words[i] = words_[i].load(std::memory_order_relaxed);
    std::atomic_thread_fence(std::memory_order_acquire);
    if (sequence_.load(std::memory_order_relaxed) != before) return std::nullopt;
    T value;
    std::memcpy(static_cast<void*>(&value), words.data(), sizeof(T));
    return value;
  }

 private:
  template <class>
  friend struct LatestValueTestPeer;  // stands for a writer stopped in the middle of a store

  std::atomic<std::uint64_t> sequence_{0};
  std::array<std::atomic<std::uint64_t>, kWords> words_{};
};

}  // namespace cyber::daemon::io
