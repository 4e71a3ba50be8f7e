// Typed access to parsed JSON with located messages (spec/formats.md#json-errors).
#include "pathref/io/json_reader.hpp"

#include <cmath>

#include "pathref/io/json_text.hpp"

namespace pathref::io {

void JsonReader::fail(const std::string& pointer, const std::string& what) const {
  throw json_error_at(text_, file_, pointer, what);
}

std::string JsonReader::kind(const Json& v) {
  if (v.is_number_float() || v.is_binary()) return "a non-integer number";
  if (v.is_number()) return "an integer";
  return json_kind(v);
}

std::string JsonReader::fmt(double x) { return Json(x).dump(); }

std::string JsonReader::child(const std::string& pointer, std::string_view key) {
  std::string out = pointer + "/";
  for (const char c : key) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out += c;
  }
  return out;
}

double JsonReader::number(const Json& v, const std::string& ptr, double lo, double hi, bool lo_open) const {
  const std::string want = std::string("expected a number in ") + (lo_open ? "(" : "[") + fmt(lo) + ", " + fmt(hi) + "]";
  if (!v.is_number()) fail(ptr, want + ", got " + kind(v));
  const double x = v.get<double>();
  if (!std::isfinite(x) || x < lo || x > hi || (lo_open && x == lo)) fail(ptr, want + ", got " + fmt(x));
  return x;
}

std::int64_t JsonReader::integer(const Json& v, const std::string& ptr, std::int64_t lo, std::int64_t hi) const {
  const std::string want = "expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (v.is_number_unsigned()) {
    const auto u = v.get<std::uint64_t>();
    if (u > static_cast<std::uint64_t>(hi)) fail(ptr, want + ", got " + std::to_string(u));
    if (static_cast<std::int64_t>(u) < lo) fail(ptr, want + ", got " + std::to_string(u));
    return static_cast<std::int64_t>(u);
  }
  if (v.is_number_integer()) {
    const auto i = v.get<std::int64_t>();
    if (i < lo || i > hi) fail(ptr, want + ", got " + std::to_string(i));
    return i;
  }
  fail(ptr, want + ", got " + kind(v));
}

std::string JsonReader::string(const Json& v, const std::string& ptr) const {
  if (!v.is_string()) fail(ptr, "expected a string, got " + kind(v));
  return v.get<std::string>();
}

bool JsonReader::boolean(const Json& v, const std::string& ptr) const {
  if (!v.is_boolean()) fail(ptr, "expected true or false, got " + kind(v));
  return v.get<bool>();
}

const nlohmann::json& JsonReader::array(const Json& v, const std::string& ptr, std::size_t max_size) const {
  if (!v.is_array()) fail(ptr, "expected an array, got " + kind(v));
  if (v.size() > max_size)
    fail(ptr, "expected an array of at most " + std::to_string(max_size) + " elements, got " + std::to_string(v.size()));
  return v;
}

const nlohmann::json& JsonReader::need(const Json& obj, const std::string& ptr, const char* key,
                                       std::string_view expected) const {
  if (!obj.is_object()) fail(ptr, "expected an object, got " + kind(obj));
  const auto it = obj.find(key);
  if (it == obj.end()) fail(ptr, std::string("missing key \"") + key + "\" (expected " + std::string(expected) + ")");
  return *it;
}

void JsonReader::keys(const Json& obj, const std::string& ptr, std::initializer_list<const char*> allowed) const {
  if (!obj.is_object()) fail(ptr, "expected an object, got " + kind(obj));
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    bool ok = false;
    for (const char* k : allowed) ok = ok || it.key() == k;
    if (!ok) {
      std::string list;
      for (const char* k : allowed) list += std::string(list.empty() ? "" : ", ") + k;
      fail(child(ptr, it.key()), "unknown key (expected one of: " + list + ")");
    }
  }
}

}  // namespace pathref::io
