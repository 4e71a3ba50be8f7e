// Fuzz target: one answer line of a `pathref conform` program (spec/conform.md#protocol), read and
// judged as cmd_conform does: io::parse_json_text under io::answer_limits, then golden::judge
// against fixed tests of grid.index (a valid test, an invalid test, a valid test with a tolerance).
//
// INVARIANT: for every byte string t, parsing t either returns a JSON value or throws
// pathref::ParseError (never another exception, never UB, never a recursion deeper than 64
// levels, also when the value is destroyed, compared or printed). For an object answer, judge
// returns for each fixed test a message of at most 4096 bytes without raw control or non-ASCII
// bytes (what conform prints is bounded whatever the program answers), and the empty message
// exactly when the answer is the expected one for the two exact tests. A broken invariant traps.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "pathref/core/error.hpp"
#include "pathref/golden/runner.hpp"
#include "pathref/io/json_text.hpp"

namespace {
using Json = nlohmann::json;

const Json& group() {
  static const Json g = Json::parse(R"({"tolerance": {"abs": 0, "rel": 0, "why": "integers"}, "tests": []})");
  return g;
}
const Json& valid_test() {
  static const Json t = Json::parse(
      R"({"tcId": 1, "result": "valid", "input": {"width": 6, "height": 6, "cell": [5, 5]}, "expected": {"index": 35}})");
  return t;
}
const Json& invalid_test() {
  static const Json t = Json::parse(
      R"({"tcId": 2, "result": "invalid", "input": {"width": 0, "height": 6, "cell": [0, 0]}, "expected": {"error": "DomainError"}})");
  return t;
}
const Json& tolerant_test() {
  static const Json t = Json::parse(
      R"({"tcId": 3, "result": "valid", "tolerance": {"abs": 1e-9, "rel": 1e-12, "why": "fuzz"}, "input": {},
          "expected": {"x": 0.1, "v": [1, 2.5, "inf", "nan"], "o": {"b": true, "s": "a"}}})");
  return t;
}

void check_message(const std::string& m) {
  if (m.size() > 4096) __builtin_trap();
  for (const char c : m) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u >= 0x7f) __builtin_trap();
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace pathref;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  Json got;
  try {
    got = io::parse_json_text(text, "the answer", 1, io::answer_limits);
  } catch (const ParseError&) {
    return 0;
  }
  if (!got.is_object()) return 0;
  // as cmd_conform: an error answer is judged as {error, message}; an output object as itself
  Json actual;
  if (got.contains("error")) {
    actual = Json{{"error", got.at("error")},
                  {"message", got.contains("message") && got.at("message").is_string() ? got.at("message") : Json("")}};
  } else if (got.contains("output") && got.at("output").is_object()) {
    actual = got.at("output");
  } else {
    return 0;
  }
  for (const Json* t : {&valid_test(), &invalid_test(), &tolerant_test()}) {
    const std::string why = golden::judge(group(), *t, actual);
    check_message(why);
  }
  const bool right_value = !got.contains("error") && actual.is_object() && actual.contains("index") &&
                           actual.at("index").is_number() && actual.at("index").get<double>() == 35.0;
  // (numbers are judged by value: 35.0 answers the integer 35, spec/golden-format.md "Comparison")
  if (right_value != golden::judge(group(), valid_test(), actual).empty()) __builtin_trap();
  const bool right_error = got.contains("error") && got.at("error") == "DomainError";
  if (right_error != golden::judge(group(), invalid_test(), actual).empty()) __builtin_trap();
  return 0;
}
