#pragma once
/// \file json_reader.hpp
/// Typed access to a parsed JSON document with messages that name the file, the line and column
/// of the offending value (when the document's text is at hand) and its JSON pointer, and say what
/// was expected (spec/formats.md#json-errors). The one helper every JSON format reader uses
/// (scenes, simulation scenarios 1 and 2, model files, golden files), so their messages agree.
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "pathref/core/error.hpp"

namespace pathref::io {

class JsonReader {
 public:
  using Json = nlohmann::json;

  /// `file` names the document in messages; `text` is its JSON text (for line and column; empty
  /// for a value that came from no file, then messages carry the pointer only). `text` must
  /// outlive the reader.
  JsonReader(std::string_view file, std::string_view text) : file_(file), text_(text) {}

  /// Throws the ParseError `FILE:LINE:COLUMN: POINTER: WHAT` (json_error_at).
  [[noreturn]] void fail(const std::string& pointer, const std::string& what) const;

  /// "a non-integer number", "an integer", "a string", "an array", "an object", "a boolean", "null".
  [[nodiscard]] static std::string kind(const Json& v);
  /// A double as JSON writes it (shortest round trip).
  [[nodiscard]] static std::string fmt(double x);
  /// `pointer` + "/" + `key` with '~' and '/' escaped (RFC 6901).
  [[nodiscard]] static std::string child(const std::string& pointer, std::string_view key);

  /// A finite number in [lo, hi] ((lo, hi] when lo_open).
  [[nodiscard]] double number(const Json& v, const std::string& ptr, double lo, double hi, bool lo_open = false) const;
  /// An integer in [lo, hi] (a JSON number without fraction or exponent).
  [[nodiscard]] std::int64_t integer(const Json& v, const std::string& ptr, std::int64_t lo, std::int64_t hi) const;
  [[nodiscard]] std::string string(const Json& v, const std::string& ptr) const;
  [[nodiscard]] bool boolean(const Json& v, const std::string& ptr) const;
  /// An array (of any size up to max_size).
  const Json& array(const Json& v, const std::string& ptr, std::size_t max_size) const;
  /// The member `key` of object `obj` (at `ptr`), or a ParseError "missing key" at the object.
  const Json& need(const Json& obj, const std::string& ptr, const char* key, std::string_view expected) const;
  /// Fails unless `obj` is an object whose keys are all in `allowed`.
  void keys(const Json& obj, const std::string& ptr, std::initializer_list<const char*> allowed) const;

 private:
  std::string file_;
  std::string_view text_;
};

/// The member `key` of `obj` (an object), or nullptr.
[[nodiscard]] inline const nlohmann::json* find(const nlohmann::json& obj, const char* key) {
  if (!obj.is_object()) return nullptr;
  const auto it = obj.find(key);
  return it == obj.end() ? nullptr : &*it;
}

}  // namespace pathref::io
