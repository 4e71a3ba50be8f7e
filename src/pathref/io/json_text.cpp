// The one JSON reading layer (spec/formats.md#json).
#include "pathref/io/json_text.hpp"

#include <fmt/format.h>

#include <charconv>
#include <vector>

namespace pathref::io {

using Json = nlohmann::json;

std::pair<std::size_t, std::size_t> line_column(std::string_view text, std::size_t byte) {
  std::size_t line = 1, col = 1;
  for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
  }
  return {line, col};
}

std::string printable(std::string_view text, std::size_t max_bytes) {
  std::string out;
  const std::size_t n = text.size() < max_bytes ? text.size() : max_bytes;
  out.reserve(n + 8);
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 || c >= 0x7F) {
      out += fmt::format("\\x{:02X}", c);
    } else {
      out += static_cast<char>(c);
    }
  }
  if (n < text.size()) out += "...";
  return out;
}

std::string json_kind(const Json& v) {
  switch (v.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::boolean: return "a boolean";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float: return "a number";
    case Json::value_t::string: return "a string";
    case Json::value_t::array: return "an array";
    case Json::value_t::object: return "an object";
    case Json::value_t::binary: return "a number";  // decimal_text keeps a float's text as binary
    case Json::value_t::discarded: break;
  }
  return "nothing";
}

namespace {

// ------------------------------------------------------------------ scanning a text nlohmann read

/// The offset just past the string token that starts at `i` (text[i] == '"').
std::size_t skip_string(std::string_view t, std::size_t i) {
  ++i;
  while (i < t.size() && t[i] != '"') i += t[i] == '\\' ? std::size_t{2} : std::size_t{1};
  return i < t.size() ? i + 1 : t.size();
}

bool is_ws(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

std::size_t skip_ws(std::string_view t, std::size_t i) {
  while (i < t.size() && is_ws(t[i])) ++i;
  return i;
}

/// The offset of the `k`-th (1-based) '[' or '{' of `t` outside strings; t.size() when absent.
std::size_t nth_open(std::string_view t, std::size_t k) {
  for (std::size_t i = 0; i < t.size();) {
    if (t[i] == '"') {
      i = skip_string(t, i);
      continue;
    }
    if ((t[i] == '[' || t[i] == '{') && --k == 0) return i;
    ++i;
  }
  return t.size();
}

/// The offset of the `k`-th (1-based) object key of `t` (a string followed by ':').
std::size_t nth_key(std::string_view t, std::size_t k) {
  for (std::size_t i = 0; i < t.size();) {
    if (t[i] == '"') {
      const std::size_t end = skip_string(t, i);
      const std::size_t after = skip_ws(t, end);
      if (after < t.size() && t[after] == ':' && --k == 0) return i;
      i = end;
      continue;
    }
    ++i;
  }
  return t.size();
}

/// The offset just past the value that starts at `i` (bounded work, no recursion).
std::size_t skip_value(std::string_view t, std::size_t i) {
  if (i >= t.size()) return t.size();
  if (t[i] == '"') return skip_string(t, i);
  if (t[i] == '[' || t[i] == '{') {
    std::size_t depth = 0;
    while (i < t.size()) {
      const char c = t[i];
      if (c == '"') {
        i = skip_string(t, i);
        continue;
      }
      if (c == '[' || c == '{') ++depth;
      if (c == ']' || c == '}') {
        if (--depth == 0) return i + 1;
      }
      ++i;
    }
    return t.size();
  }
  while (i < t.size() && t[i] != ',' && t[i] != ']' && t[i] != '}' && !is_ws(t[i])) ++i;
  return i;
}

/// The decoded text of the string token at `i` (escapes resolved); "" when it does not decode.
std::string decode_string(std::string_view t, std::size_t i) {
  const std::size_t end = skip_string(t, i);
  try {
    return Json::parse(t.substr(i, end - i)).get<std::string>();
  } catch (const Json::exception&) {
    return {};
  }
}

/// The reference tokens of JSON pointer `p` ("~1" -> '/', "~0" -> '~').
std::vector<std::string> pointer_tokens(std::string_view p) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < p.size() && p[i] == '/') {
    std::string tok;
    ++i;
    while (i < p.size() && p[i] != '/') {
      if (p[i] == '~' && i + 1 < p.size() && (p[i + 1] == '0' || p[i + 1] == '1')) {
        tok += p[i + 1] == '0' ? '~' : '/';
        i += 2;
      } else {
        tok += p[i++];
      }
    }
    out.push_back(std::move(tok));
  }
  return out;
}

// ------------------------------------------------------------------ the bounded DOM builder

enum class Refusal { none, syntax, size, depth, duplicate_key };

/// A SAX consumer that builds the value, refusing a container one level deeper than the limit
/// (before building it) and a key its object already has. It counts container openings and keys,
/// so the refusal's byte can be found again in the text (nth_open, nth_key).
class BoundedDom {
 public:
  BoundedDom(Json& root, const JsonLimits& limits) : root_(root), limits_(limits) {}

  bool null() { return put(Json(nullptr)); }
  bool boolean(bool v) { return put(Json(v)); }
  bool number_integer(Json::number_integer_t v) { return put(Json(v)); }
  bool number_unsigned(Json::number_unsigned_t v) { return put(Json(v)); }
  bool number_float(Json::number_float_t v, const Json::string_t& text) {
    if (limits_.decimal_text) return put(Json::binary(Json::binary_t::container_type(text.begin(), text.end())));
    return put(Json(v));
  }
  bool string(Json::string_t& v) { return put(Json(std::move(v))); }
  bool binary(Json::binary_t& v) { return put(Json::binary(v)); }
  bool start_object(std::size_t) { return open(Json::object()); }
  bool key(Json::string_t& k) {
    ++keys_;
    if (stack_.back()->contains(k)) {
      refusal_ = Refusal::duplicate_key;
      message_ = "an object with distinct keys (the key \"" + printable(k) + "\" appears twice)";
      return false;
    }
    key_ = std::move(k);
    return true;
  }
  bool end_object() {
    stack_.pop_back();
    return true;
  }
  bool start_array(std::size_t) { return open(Json::array()); }
  bool end_array() {
    stack_.pop_back();
    return true;
  }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& e) {
    refusal_ = Refusal::syntax;
    position_ = position;
    message_ = e.what();
    return false;
  }

  [[nodiscard]] Refusal refusal() const noexcept { return refusal_; }
  [[nodiscard]] const std::string& message() const noexcept { return message_; }
  [[nodiscard]] std::size_t position() const noexcept { return position_; }
  [[nodiscard]] std::size_t opens() const noexcept { return opens_; }
  [[nodiscard]] std::size_t keys() const noexcept { return keys_; }

 private:
  bool put(Json v) {
    if (stack_.empty()) {
      root_ = std::move(v);
      return true;
    }
    Json& parent = *stack_.back();
    if (parent.is_array()) {
      parent.push_back(std::move(v));
    } else {
      parent[key_] = std::move(v);
    }
    return true;
  }
  bool open(Json v) {
    ++opens_;
    if (stack_.size() >= limits_.max_depth) {
      refusal_ = Refusal::depth;
      message_ = fmt::format("JSON nested at most {} levels deep (arrays and objects)", limits_.max_depth);
      return false;
    }
    if (stack_.empty()) {
      root_ = std::move(v);
      stack_.push_back(&root_);
      return true;
    }
    Json& parent = *stack_.back();
    if (parent.is_array()) {
      parent.push_back(std::move(v));
      stack_.push_back(&parent.back());
    } else {
      Json& slot = parent[key_];
      slot = std::move(v);
      stack_.push_back(&slot);
    }
    return true;
  }

  Json& root_;
  const JsonLimits& limits_;
  std::vector<Json*> stack_;
  std::string key_;
  Refusal refusal_ = Refusal::none;
  std::string message_;
  std::size_t position_ = 0;
  std::size_t opens_ = 0;
  std::size_t keys_ = 0;
};

/// nlohmann's parse-error text without its "[json.exception...] parse error at line L, column C: "
/// prefix (the position is ours) and with the echoed input made printable.
std::string syntax_message(const std::string& what) {
  std::string_view w = what;
  if (const auto col = w.find(", column "); col != std::string_view::npos) {
    if (const auto colon = w.find(": ", col); colon != std::string_view::npos) w.remove_prefix(colon + 2);
  } else if (const auto br = w.find("] "); br != std::string_view::npos && w.substr(0, 1) == "[") {
    w.remove_prefix(br + 2);
  }
  return printable(w, 300);
}

struct Outcome {
  Refusal refusal = Refusal::none;
  std::size_t byte = 0;  ///< 0-based offset of the refusal
  std::string message;   ///< what was expected
};

Outcome parse_bounded(std::string_view text, const JsonLimits& limits, Json& out) {
  if (text.size() > limits.max_bytes)
    return {Refusal::size, 0,
            fmt::format("a JSON text of at most {} bytes; this one has {} bytes", limits.max_bytes, text.size())};
  if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF")
    return {Refusal::syntax, 0,
            "JSON text without a byte order mark (found the UTF-8 BOM EF BB BF; RFC 8259 section 8.1: save the file "
            "as UTF-8 without BOM)"};
  BoundedDom dom(out, limits);
  bool ok = false;
  std::string library_error;
  try {
    ok = Json::sax_parse(text.begin(), text.end(), &dom, Json::input_format_t::json, /*strict=*/true);
  } catch (const Json::exception& e) {  // out_of_range 406 (a number too large for a double) is thrown
    library_error = e.what();
  }
  if (ok) return {};
  out = Json();
  switch (dom.refusal()) {
    case Refusal::size: break;
    case Refusal::depth:
      return {Refusal::depth, nth_open(text, dom.opens()), dom.message()};
    case Refusal::duplicate_key:
      return {Refusal::duplicate_key, nth_key(text, dom.keys()), dom.message()};
    case Refusal::syntax: {
      const std::string what = syntax_message(dom.message());
      const bool overflow = what.find("number overflow") != std::string::npos;
      return {Refusal::syntax, dom.position() > 0 ? dom.position() - 1 : 0,
              (overflow ? "a number within the range of a double (" : "valid JSON (") + what + ")"};
    }
    case Refusal::none: break;
  }
  // The thrown error: find where with a second, value-less pass that stops at the same byte.
  class Where final : public nlohmann::json_sax<Json> {
   public:
    bool null() override { return true; }
    bool boolean(bool) override { return true; }
    bool number_integer(number_integer_t) override { return true; }
    bool number_unsigned(number_unsigned_t) override { return true; }
    bool number_float(number_float_t, const string_t&) override { return true; }
    bool string(string_t&) override { return true; }
    bool binary(binary_t&) override { return true; }
    bool start_object(std::size_t) override { return true; }
    bool key(string_t&) override { return true; }
    bool end_object() override { return true; }
    bool start_array(std::size_t) override { return true; }
    bool end_array() override { return true; }
    bool parse_error(std::size_t p, const std::string&, const nlohmann::detail::exception&) override {
      position = p;
      return false;
    }
    std::size_t position = 0;
  } where;
  try {
    (void)Json::sax_parse(text.begin(), text.end(), &where, Json::input_format_t::json, true);
  } catch (const Json::exception&) {
  }
  const bool too_large = library_error.find("406") != std::string::npos;
  return {Refusal::syntax, where.position > 0 ? where.position - 1 : 0,
          too_large ? "a number within the range of a double (" + syntax_message(library_error) + ")"
                    : "valid JSON (" + syntax_message(library_error) + ")"};
}

}  // namespace

Json parse_json_text(std::string_view text, std::string_view file, std::size_t first_line, const JsonLimits& limits) {
  Json out;
  const Outcome o = parse_bounded(text, limits, out);
  if (o.refusal == Refusal::none) return out;
  const auto [line, col] = line_column(text, o.byte);
  throw ParseError(std::string(file), first_line - 1 + line, col, "expected " + o.message);
}

std::optional<Json> parse_cli_json_value(std::string_view text, std::string_view what) {
  Json out;
  const Outcome o = parse_bounded(text, cli_value_limits, out);
  if (o.refusal == Refusal::none) return out;
  if (o.refusal == Refusal::syntax) return std::nullopt;
  throw UsageError(fmt::format("{}: expected {} (at character {} of the value)", what, o.message, o.byte + 1));
}

std::size_t pointer_offset(std::string_view t, std::string_view pointer) {
  std::size_t at = skip_ws(t, 0);
  for (const std::string& tok : pointer_tokens(pointer)) {
    if (at >= t.size()) return at;
    if (t[at] == '{') {
      std::size_t i = skip_ws(t, at + 1);
      bool found = false;
      while (i < t.size() && t[i] == '"') {
        const std::string key = decode_string(t, i);
        i = skip_ws(t, skip_string(t, i));
        if (i < t.size() && t[i] == ':') i = skip_ws(t, i + 1);
        if (key == tok) {
          found = true;
          break;
        }
        i = skip_ws(t, skip_value(t, i));
        if (i < t.size() && t[i] == ',') i = skip_ws(t, i + 1);
      }
      if (!found) return at;
      at = i;
    } else if (t[at] == '[') {
      std::size_t index = 0;
      const auto r = std::from_chars(tok.data(), tok.data() + tok.size(), index);
      if (tok.empty() || r.ec != std::errc() || r.ptr != tok.data() + tok.size()) return at;
      std::size_t i = skip_ws(t, at + 1);
      for (std::size_t n = 0; n < index; ++n) {
        if (i >= t.size() || t[i] == ']') return at;
        i = skip_ws(t, skip_value(t, i));
        if (i < t.size() && t[i] == ',') i = skip_ws(t, i + 1);
      }
      if (i >= t.size() || t[i] == ']') return at;
      at = i;
    } else {
      return at;
    }
  }
  return at;
}

ParseError json_error_at(std::string_view text, std::string_view file, std::string_view pointer,
                         const std::string& what, std::size_t first_line) {
  const std::string where = pointer.empty() ? std::string("/") : std::string(pointer);
  if (text.empty()) return ParseError(std::string(file), where + ": " + what);
  const auto [line, col] = line_column(text, pointer_offset(text, pointer));
  return ParseError(std::string(file), first_line - 1 + line, col, where + ": " + what);
}

}  // namespace pathref::io
