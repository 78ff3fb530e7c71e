// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/machine/profile_json.hpp"

#include <cmath>

namespace fivebar::detail {
namespace {

Message typeName(const nlohmann::json& v) {
  if (v.is_number()) return FB_TR("Profile", "a number");
  if (v.is_string()) return FB_TR("Profile", "a string");
  if (v.is_boolean()) return FB_TR("Profile", "a boolean");
  if (v.is_object()) return FB_TR("Profile", "an object");
  if (v.is_array()) return FB_TR("Profile", "an array");
  if (v.is_null()) return FB_TR("Profile", "null");
  return FB_TR("Profile", "an unsupported value");
}

}  // namespace

ObjectReader::ObjectReader(const nlohmann::json& object, std::string path,
                           std::vector<ValidationIssue>& issues)
    : object_(object), path_(std::move(path)), issues_(issues), isObject_(object.is_object()) {}

std::string ObjectReader::pathOf(const char* key) const {
  return path_.empty() ? std::string(key) : path_ + "." + key;
}

const nlohmann::json* ObjectReader::member(const char* key, bool required) {
  known_.insert(key);
  if (!isObject_) return nullptr;
  auto it = object_.find(key);
  if (it == object_.end()) {
    if (required) issues_.push_back({pathOf(key), FB_TR("Profile", "%1 is missing (it is required)").arg(pathOf(key))});
    return nullptr;
  }
  return &*it;
}

void ObjectReader::typeError(const char* key, Message expected, const nlohmann::json& value) {
  issues_.push_back({pathOf(key), value.is_string()
                                      ? FB_TR("Profile", "%1 must be %2, got %3 \"%4\"")
                                            .arg(pathOf(key))
                                            .arg(std::move(expected))
                                            .arg(typeName(value))
                                            .arg(value.get<std::string>())
                                      : FB_TR("Profile", "%1 must be %2, got %3")
                                            .arg(pathOf(key))
                                            .arg(std::move(expected))
                                            .arg(typeName(value))});
}

void ObjectReader::number(const char* key, double& out, bool required) {
  const nlohmann::json* v = member(key, required);
  if (!v) return;
  if (!v->is_number()) return typeError(key, FB_TR("Profile", "a number"), *v);
  out = v->get<double>();
}

void ObjectReader::integer(const char* key, int& out, bool required) {
  const nlohmann::json* v = member(key, required);
  if (!v) return;
  if (!v->is_number_integer()) return typeError(key, FB_TR("Profile", "an integer"), *v);
  // An unsigned beyond long long's range would wrap to a negative value: out of range too.
  const bool tooLarge = v->is_number_unsigned() && v->get<unsigned long long>() > 2147483647ULL;
  const auto value = tooLarge ? 0LL : v->get<long long>();
  if (tooLarge || value < -2147483647LL || value > 2147483647LL) {
    issues_.push_back({pathOf(key), FB_TR("Profile", "%1 is out of the integer range").arg(pathOf(key))});
    return;
  }
  out = static_cast<int>(value);
}

void ObjectReader::boolean(const char* key, bool& out, bool required) {
  const nlohmann::json* v = member(key, required);
  if (!v) return;
  if (!v->is_boolean()) return typeError(key, FB_TR("Profile", "true or false"), *v);
  out = v->get<bool>();
}

void ObjectReader::string(const char* key, std::string& out, bool required) {
  const nlohmann::json* v = member(key, required);
  if (!v) return;
  if (!v->is_string()) return typeError(key, FB_TR("Profile", "a string"), *v);
  out = v->get<std::string>();
}

void ObjectReader::strings(const char* key, std::vector<std::string>& out, bool required) {
  const nlohmann::json* v = member(key, required);
  if (!v) return;
  if (!v->is_array()) return typeError(key, FB_TR("Profile", "an array of strings"), *v);
  std::vector<std::string> values;
  for (std::size_t i = 0; i < v->size(); ++i) {
    const nlohmann::json& e = (*v)[i];
    if (!e.is_string()) {
      const std::string path = pathOf(key) + "[" + std::to_string(i) + "]";
      issues_.push_back({path, FB_TR("Profile", "%1 must be a string, got %2").arg(path).arg(typeName(e))});
      return;
    }
    values.push_back(e.get<std::string>());
  }
  out = std::move(values);
}

const nlohmann::json* ObjectReader::object(const char* key, bool required) {
  const nlohmann::json* v = member(key, required);
  if (!v) return nullptr;
  if (!v->is_object()) {
    typeError(key, FB_TR("Profile", "an object"), *v);
    return nullptr;
  }
  return v;
}

void ObjectReader::finish() {
  if (!isObject_) return;
  std::string expected;
  for (const std::string& k : known_) expected += (expected.empty() ? "" : ", ") + k;
  for (auto it = object_.begin(); it != object_.end(); ++it) {
    if (known_.count(it.key())) continue;
    // The key as written, an empty one as "" and control bytes as \xNN (found by
    // fuzz/profile_json_fuzz.cpp: a key "" or "\u0000..." gave a message that began with nothing).
    std::string key;
    for (const char c : it.key()) {
      if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
        static const char kHex[] = "0123456789abcdef";
        key += "\\x";
        key += kHex[(static_cast<unsigned char>(c) >> 4) & 0xf];
        key += kHex[static_cast<unsigned char>(c) & 0xf];
      } else {
        key += c;
      }
    }
    if (key.empty()) key = "\"\"";
    const std::string path = path_.empty() ? key : path_ + "." + key;
    issues_.push_back({path, FB_TR("Profile", "%1 is not a known field (expected one of: %2)").arg(path).arg(expected)});
  }
}

namespace {
std::string withoutPrefix(std::string what) {
  if (auto colon = what.find("] "); colon != std::string::npos) what = what.substr(colon + 2);
  return what;
}
}  // namespace

std::optional<JsonSyntaxError> parseJsonText(const std::string& text, nlohmann::json& out) {
  try {
    out = nlohmann::json::parse(text);
    return std::nullopt;
  } catch (const nlohmann::json::parse_error& e) {
    return JsonSyntaxError{positionOf(text, e.byte > 0 ? e.byte - 1 : 0), withoutPrefix(e.what())};
  } catch (const nlohmann::json::exception& e) {
    // "number overflow parsing '35E5556'": point at that number's text.
    std::string what = withoutPrefix(e.what());
    std::size_t at = 0;
    const std::size_t open = what.find('\'');
    const std::size_t close = open == std::string::npos ? open : what.find('\'', open + 1);
    if (close != std::string::npos && close > open + 1) {
      const std::size_t found = text.find(what.substr(open + 1, close - open - 1));
      if (found != std::string::npos) at = found;
    }
    return JsonSyntaxError{positionOf(text, at), std::move(what)};
  }
}

TextPosition positionOf(const std::string& text, std::size_t byteOffset) {
  TextPosition pos;
  const std::size_t end = std::min(byteOffset, text.size());
  for (std::size_t i = 0; i < end; ++i) {
    if (text[i] == '\n') {
      ++pos.line;
      pos.column = 1;
    } else {
      ++pos.column;
    }
  }
  return pos;
}

}  // namespace fivebar::detail
