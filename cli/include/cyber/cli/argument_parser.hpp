#pragma once
// One option syntax for every program: `--name VALUE` and `--name=VALUE` mean the same, a flag
// takes no value (`--flag=x` is an error), a value is never empty (`--name=` and `--name ""` are
// errors), `--help`/`-h` stops the scan. Handlers check and store each value as it comes.

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cyber/cli/argument_status.hpp"

namespace cyber::cli {

// What a value handler says: "" when the value is taken, else the reason it is refused (the
// parser prefixes the option's name).
using ValueHandler = std::function<std::string(const std::string& value)>;

// A handler that keeps the value as it is in `into`, which must outlive the parse.
ValueHandler store(std::string& into);
ValueHandler store(std::optional<std::string>& into);

enum class Scan { kComplete, kHelp };

class ArgumentParser {
 public:
  void flag(std::string name, std::function<void()> set);
  void option(std::string name, ValueHandler take);
  // Arguments that are not options (including "-"); without a handler they are errors.
  void positional(ValueHandler take);

  [[nodiscard]] Result<Scan, ArgumentStatus> parse(const std::vector<std::string>& args) const;

  // The start of every program's parse function: scans `args` (the handlers store into `out`) and
  // returns the result when the scan alone decides it: the error, or `out` with `help` set after
  // --help/-h. Nothing: the program's own checks of the whole line follow.
  template <class Arguments>
  [[nodiscard]] std::optional<Result<Arguments, ArgumentStatus>> parseInto(const std::vector<std::string>& args,
                                                                           Arguments& out) const {
    // Built in place: a temporary Result moved into the optional trips GCC 12's
    // -Wmaybe-uninitialized on the variant it holds.
    const Result<Scan, ArgumentStatus> scan = parse(args);
    if (!scan) return std::optional<Result<Arguments, ArgumentStatus>>(std::in_place, scan.error());
    if (scan.value() != Scan::kHelp) return std::nullopt;
    out.help = true;
    return std::optional<Result<Arguments, ArgumentStatus>>(std::in_place, out);
  }

 private:
  struct Entry {
    std::string name;
    bool takes_value = false;
    std::function<void()> set;
    ValueHandler take;
  };
  [[nodiscard]] const Entry* find(std::string_view name) const;

  std::vector<Entry> entries_;
  ValueHandler positional_;
};

}  // namespace cyber::cli
