// SPDX-License-Identifier: GPL-3.0-or-later
// Minimal, strict option parsing for the CLI: "--name value" and "--flag" forms, every unknown
// option is an error that names it.
#pragma once

#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace fivebar::cli {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The value of a numeric option, whole ("12.5", not "12.5mm"), finite and, when `positive`,
// above zero; anything else is a UsageError naming the option and the text given.
inline double numberArg(const std::string& text, const std::string& option, bool positive = false) {
  size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(v) || (positive && !(v > 0.0)))
    throw UsageError(option + (positive ? " needs a positive number, got '" : " needs a number, got '") +
                     text + "'");
  return v;
}

class Options {
 public:
  // valued: options that take a value; flags: options that do not. Anything not starting with
  // "--" is a positional argument.
  Options(const std::vector<std::string>& args, const std::set<std::string>& valued,
          const std::set<std::string>& flags) {
    for (size_t i = 0; i < args.size(); ++i) {
      const std::string& a = args[i];
      if (a.rfind("--", 0) != 0 || a == "-") {
        positional_.push_back(a);
      } else if (valued.count(a)) {
        if (i + 1 >= args.size()) throw UsageError("option " + a + " needs a value");
        values_[a] = args[++i];
      } else if (flags.count(a)) {
        flags_.insert(a);
      } else {
        throw UsageError("unknown option " + a);
      }
    }
  }
  std::optional<std::string> value(const std::string& name) const {
    auto it = values_.find(name);
    return it == values_.end() ? std::nullopt : std::optional<std::string>(it->second);
  }
  std::string required(const std::string& name) const {
    auto v = value(name);
    if (!v) throw UsageError("missing required option " + name);
    return *v;
  }
  bool flag(const std::string& name) const { return flags_.count(name) > 0; }
  const std::vector<std::string>& positional() const { return positional_; }

 private:
  std::map<std::string, std::string> values_;
  std::set<std::string> flags_;
  std::vector<std::string> positional_;
};

}  // namespace fivebar::cli
