#include "cyber/cli/argument_parser.hpp"

#include <utility>

namespace cyber::cli {

ValueHandler store(std::string& into) {
  return [&into](const std::string& value) {
    into = value;
    return std::string();
  };
}

ValueHandler store(std::optional<std::string>& into) {
  return [&into](const std::string& value) {
    into = value;
    return std::string();
  };
}

void ArgumentParser::flag(std::string name, std::function<void()> set) {
  entries_.push_back(Entry{std::move(name), false, std::move(set), {}});
}

void ArgumentParser::option(std::string name, ValueHandler take) {
  entries_.push_back(Entry{std::move(name), true, {}, std::move(take)});
}

void ArgumentParser::positional(ValueHandler take) { positional_ = std::move(take); }

const ArgumentParser::Entry* ArgumentParser::find(std::string_view name) const {
  for (const Entry& e : entries_) {
    if (e.name == name) return &e;
  }
  return nullptr;
}

Result<Scan, ArgumentStatus> ArgumentParser::parse(const std::vector<std::string>& args) const {
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg == "--help" || arg == "-h") return Scan::kHelp;
    if (arg.size() < 2 || arg[0] != '-') {
      if (!positional_) return badUsage("unexpected argument '" + arg + "' (see --help)");
      if (std::string reason = positional_(arg); !reason.empty()) return badUsage(std::move(reason));
      continue;
    }
    const std::size_t equals = arg.find('=');
    const std::string name = arg.substr(0, equals);
    const Entry* entry = find(name);
    if (entry == nullptr) return badUsage("unknown argument '" + arg + "' (see --help)");
    if (!entry->takes_value) {
      if (equals != std::string::npos) return badUsage(name + " takes no value, got '" + arg + "'");
      entry->set();
      continue;
    }
    std::string value;
    if (equals != std::string::npos) {
      value = arg.substr(equals + 1);
    } else if (i + 1 < args.size()) {
      value = args[++i];
    }
    if (value.empty()) return badUsage(name + " needs a value");
    if (std::string reason = entry->take(value); !reason.empty()) return badUsage(name + " " + reason);
  }
  return Scan::kComplete;
}

}  // namespace cyber::cli
