// SPDX-License-Identifier: GPL-3.0-or-later
// Translatable core messages. Contract: message.hpp.
#include "core/support/message.hpp"

#include <algorithm>
#include <charconv>
#include <ostream>

namespace fivebar {
namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }

// A marker at templ[i] ('%'): its number (1..99) and length, or number 0 when there is none.
struct Marker {
  int number = 0;
  std::size_t length = 0;
};
Marker markerAt(std::string_view templ, std::size_t i) {
  std::size_t j = i + 1;
  if (j < templ.size() && templ[j] == 'L') ++j;
  if (j >= templ.size() || !isDigit(templ[j])) return {};
  int n = templ[j] - '0';
  ++j;
  if (j < templ.size() && isDigit(templ[j])) n = 10 * n + (templ[j++] - '0');
  if (n == 0) return {};
  return {n, j - i};
}

}  // namespace

std::string substituteArgs(std::string_view templ, const std::vector<std::string>& args) {
  std::vector<int> numbers;  // distinct marker numbers, ascending
  for (std::size_t i = 0; i < templ.size(); ++i)
    if (templ[i] == '%')
      if (const Marker m = markerAt(templ, i); m.number > 0) numbers.push_back(m.number);
  std::sort(numbers.begin(), numbers.end());
  numbers.erase(std::unique(numbers.begin(), numbers.end()), numbers.end());
  std::string out;
  out.reserve(templ.size() + 16 * args.size());
  for (std::size_t i = 0; i < templ.size();) {
    if (templ[i] == '%') {
      const Marker m = markerAt(templ, i);
      if (m.number > 0) {
        const auto rank = static_cast<std::size_t>(
            std::lower_bound(numbers.begin(), numbers.end(), m.number) - numbers.begin());
        if (rank < args.size()) {
          out += args[rank];
          i += m.length;
          continue;
        }
      }
    }
    out += templ[i++];
  }
  return out;
}

std::string fixedText(double value, int decimals) {
  char b[400];  // DBL_MAX has 309 digits before the point
  const auto r = std::to_chars(b, b + sizeof b, value, std::chars_format::fixed,
                               std::clamp(decimals, 0, 17));
  if (r.ec != std::errc()) return "?";
  return std::string(b, r.ptr);  // as printf("%.*f") in the C locale, "-0.0" included
}

std::string significantText(double value, int digits) {
  char b[64];
  const auto r = std::to_chars(b, b + sizeof b, value, std::chars_format::general,
                               std::clamp(digits, 1, 17));
  if (r.ec != std::errc()) return "?";
  return std::string(b, r.ptr);  // as printf("%.*g") in the C locale
}

Message& Message::arg(std::string text) & {
  args_.push_back({MessageArg::Kind::Text, std::move(text), 0.0, 0, nullptr});
  return *this;
}
Message& Message::arg(const char* text) & { return arg(std::string(text)); }
Message& Message::arg(std::string_view text) & { return arg(std::string(text)); }
Message& Message::arg(int value) & { return arg(std::to_string(value)); }
Message& Message::arg(long long value) & { return arg(std::to_string(value)); }
Message& Message::arg(std::size_t value) & { return arg(std::to_string(value)); }
Message& Message::arg(double value, int decimals) & {
  args_.push_back({MessageArg::Kind::Number, {}, value, decimals, nullptr});
  return *this;
}
Message& Message::argSignificant(double value, int digits) & {
  args_.push_back({MessageArg::Kind::Number, {}, value, digits, nullptr, true});
  return *this;
}
Message& Message::inStudio(Message studioWording) & {
  studio_ = std::make_shared<const Message>(std::move(studioWording));
  return *this;
}
Message& Message::arg(Message nested) & {
  args_.push_back({MessageArg::Kind::Nested, {}, 0.0, 0,
                   std::make_shared<const Message>(std::move(nested))});
  return *this;
}

std::string Message::text() const {
  if (args_.empty() || context_.empty()) return templ_;
  std::vector<std::string> texts;
  texts.reserve(args_.size());
  for (const MessageArg& a : args_) {
    switch (a.kind) {
      case MessageArg::Kind::Text: texts.push_back(a.text); break;
      case MessageArg::Kind::Number:
        texts.push_back(a.significant ? significantText(a.value, a.decimals)
                                      : fixedText(a.value, a.decimals));
        break;
      case MessageArg::Kind::Nested: texts.push_back(a.message->text()); break;
    }
  }
  return substituteArgs(templ_, texts);
}

std::ostream& operator<<(std::ostream& out, const Message& message) { return out << message.text(); }

}  // namespace fivebar
