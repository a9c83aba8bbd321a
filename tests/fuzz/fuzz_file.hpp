#pragma once
// For targets whose code under test takes a path: the input's bytes in a memfd, named by its
// /proc/self/fd path (opened afresh by each reader, so it reads from the start).

#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_check.hpp"

namespace cyber::fuzz {

class FuzzFile {
 public:
  FuzzFile() : fd_(memfd_create("cyber-fuzz-input", 0)), path_("/proc/self/fd/" + std::to_string(fd_)) {
    CYBER_FUZZ_CHECK(fd_ >= 0);
  }
  // Replaces the contents with data[0, size) and returns the path.
  const std::string& write(const std::uint8_t* data, std::size_t size) {
    CYBER_FUZZ_CHECK(ftruncate(fd_, 0) == 0);
    std::size_t written = 0;
    while (written < size) {
      const ssize_t n = pwrite(fd_, data + written, size - written, static_cast<off_t>(written));
      CYBER_FUZZ_CHECK(n > 0);
      written += static_cast<std::size_t>(n);
    }
    return path_;
  }

 private:
  int fd_;
  std::string path_;
};

}  // namespace cyber::fuzz
