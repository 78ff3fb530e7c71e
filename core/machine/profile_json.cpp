#include "core/machine/profile_json.hpp"

#include <cmath>
#include <sstream>

namespace fivebar::detail {
namespace {

const char* typeName(const nlohmann::json& v) {
  if (v.is_number()) return "a number";
  if (v.is_string()) return "a string";
  if (v.is_boolean()) return "a boolean";
  if (v.is_object()) return "an object";
  if (v.is_array()) return "an array";
  if (v.is_null()) return "null";
  return "an unsupported value";
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
    if (required) issues_.push_back({pathOf(key), pathOf(key) + " is missing (it is required)"});
    return nullptr;
  }
  return &*it;
}

void ObjectReader::typeError(const char* key, const char* expected, const nlohmann::json& value) {
  std::ostringstream s;
  s << pathOf(key) << " must be " << expected << ", got " << typeName(value);
  if (value.is_string()) s << " \"" << value.get<std::string>() << "\"";
  issues_.push_back({pathOf(key), s.str()});
}

void ObjectReader::number(const char* key, double& out, bool required) {
  const nlohmann::json* v = member(key, required);
  if (!v) return;
  if (!v->is_number()) return typeError(key, "a number", *v);
  out = v->get<double>();
}

void ObjectReader::integer(const char* key, int& out, bool required) {
  const nlohmann::json* v = member(key, required);
  if (!v) return;
  if (!v->is_number_integer()) return typeError(key, "an integer", *v);
  const auto value = v->get<long long>();
  if (value < -2147483647LL || value > 2147483647LL) {
    issues_.push_back({pathOf(key), pathOf(key) + " is out of the integer range"});
    return;
  }
  out = static_cast<int>(value);
}

void ObjectReader::boolean(const char* key, bool& out, bool required) {
  const nlohmann::json* v = member(key, required);
  if (!v) return;
  if (!v->is_boolean()) return typeError(key, "true or false", *v);
  out = v->get<bool>();
}

void ObjectReader::string(const char* key, std::string& out, bool required) {
  const nlohmann::json* v = member(key, required);
  if (!v) return;
  if (!v->is_string()) return typeError(key, "a string", *v);
  out = v->get<std::string>();
}

void ObjectReader::strings(const char* key, std::vector<std::string>& out, bool required) {
  const nlohmann::json* v = member(key, required);
  if (!v) return;
  if (!v->is_array()) return typeError(key, "an array of strings", *v);
  std::vector<std::string> values;
  for (std::size_t i = 0; i < v->size(); ++i) {
    const nlohmann::json& e = (*v)[i];
    if (!e.is_string()) {
      const std::string path = pathOf(key) + "[" + std::to_string(i) + "]";
      issues_.push_back({path, path + " must be a string, got " + typeName(e)});
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
    typeError(key, "an object", *v);
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
    const std::string path = pathOf(it.key().c_str());
    issues_.push_back({path, path + " is not a known field (expected one of: " + expected + ")"});
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
