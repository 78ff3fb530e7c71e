// SPDX-License-Identifier: GPL-3.0-or-later
// A user-visible sentence of the core, kept translatable: a context and an English template with
// %1..%n markers (QString::arg conventions) plus its arguments, some of which are numbers the
// studio formats in the user's locale. The core stays free of Qt: text() gives the English
// sentence (what the CLI prints, REPORT.json and the tests read); the studio translates the
// template with QCoreApplication::translate(context, templ) and formats the numbers with QLocale
// (i18n/translated.hpp). Templates are marked for lupdate with FB_TR or FB_TR_NOOP,
// which lupdate reads as QT_TRANSLATE_NOOP (-tr-function-alias QT_TRANSLATE_NOOP+=FB_TR,...).
// Design: docs/translations.md.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

// A translatable message of the core: FB_TR("Preflight", "point %1 at (%2, %3) mm").arg(...).
// Both arguments must be string literals (lupdate extracts them).
#define FB_TR(context, templ) ::fivebar::Message(context, templ)
// Marks a translatable template kept as a plain literal (in a table); expands to the template.
#define FB_TR_NOOP(context, templ) templ

namespace fivebar {

class Message;

// One argument of a message: verbatim text (names, tags, ids, indices), a real number with
// its number of decimals, or a nested message (translated on its own).
struct MessageArg {
  enum class Kind { Text, Number, Nested };
  Kind kind = Kind::Text;
  std::string text;                        // Text
  double value = 0.0;                      // Number
  int decimals = 0;                        // Number: digits after the decimal point
  std::shared_ptr<const Message> message;  // Nested (never null when Nested)
  // Number: `decimals` counts significant digits instead, trailing zeros dropped (printf %g,
  // what an ostream writes with that precision: 0.5, 120, 1e-07).
  bool significant = false;
};

class Message {
 public:
  Message() = default;
  // A translatable template; both strings are normally literals marked with FB_TR_NOOP and the
  // context is one of the contexts of translations/*.ts (e.g. "Preflight").
  Message(std::string context, std::string templ)
      : context_(std::move(context)), templ_(std::move(templ)) {}
  // Verbatim text that is never translated (a message from a file, a library, the OS...).
  // Implicit, so that code building plain strings keeps compiling.
  Message(std::string text) : templ_(std::move(text)) {}  // NOLINT(google-explicit-constructor)
  Message(const char* text) : templ_(text) {}             // NOLINT(google-explicit-constructor)

  // Appends the next argument (%1, then %2, ...). Integers are text: indices and counts read
  // the same in every language. Real numbers are written with `decimals` digits.
  Message& arg(std::string text) &;
  Message& arg(const char* text) &;
  Message& arg(std::string_view text) &;
  Message& arg(int value) &;
  Message& arg(long long value) &;
  Message& arg(std::size_t value) &;
  Message& arg(double value, int decimals) &;
  // A real number with `digits` significant digits, as an ostream of that precision writes it.
  Message& argSignificant(double value, int digits) &;
  Message&& argSignificant(double value, int digits) && {
    argSignificant(value, digits);
    return std::move(*this);
  }
  Message& arg(Message nested) &;
  template <class... A>
  Message&& arg(A&&... a) && {
    arg(std::forward<A>(a)...);
    return std::move(*this);
  }

  // The English sentence: the template with every %n replaced by argument n (a number in the
  // C locale, a nested message by its text()).
  std::string text() const;

  // The same sentence shorter where the studio shows part of it beside the message (a problem
  // listed under its layer and path names only the point). text() stays this one's; the
  // studio's translated() shows the shorter wording instead. Core never names the studio's
  // controls: what to change is a code (core/planning/plan_fix.hpp) each front end words.
  Message& inStudio(Message studioWording) &;
  Message&& inStudio(Message studioWording) && {
    inStudio(std::move(studioWording));
    return std::move(*this);
  }
  // The studio wording, or null when the studio shows this message itself.
  const Message* studioWording() const { return studio_.get(); }

  bool translatable() const { return !context_.empty(); }
  bool empty() const { return templ_.empty(); }
  const std::string& context() const { return context_; }
  const std::string& templ() const { return templ_; }
  const std::vector<MessageArg>& args() const { return args_; }

  bool operator==(const Message& other) const { return text() == other.text(); }

 private:
  std::string context_;  // empty: verbatim, templ_ is the text itself (no substitution)
  std::string templ_;
  std::vector<MessageArg> args_;
  std::shared_ptr<const Message> studio_;  // inStudio(); null when none
};

// QString::arg(a1, a2, ...) at run time: markers are %n and %Ln (n = 1..99, two digits read
// greedily, as Qt does); the distinct marker numbers, in ascending order, take args[0], args[1],
// ... (so "%2 %3" with two arguments reads "a1 a2"); markers left without an argument and every
// other character are kept. One pass: replacements are never scanned for markers.
std::string substituteArgs(std::string_view templ, const std::vector<std::string>& args);

// A real number written with `decimals` digits after the point, in the C locale.
std::string fixedText(double value, int decimals);
// A real number with `digits` significant digits (printf %g), in the C locale.
std::string significantText(double value, int digits);

// Writes text() (the CLI prints messages in English).
std::ostream& operator<<(std::ostream& out, const Message& message);

}  // namespace fivebar
