// Fuzz target: golden files (spec/golden-format.md) as `pathref golden check` and `pathref
// conform` read them before any vector runs: io::parse_json_text then golden::check_document_shape
// (spec/golden-format.md#runner-checks).
//
// INVARIANT: for every byte string t, parsing and checking t either succeeds or throws
// pathref::ParseError (never another exception, never UB, never a recursion deeper than the JSON
// layer's 64 levels) whose message holds no raw control byte. When the check succeeds the document
// is an object with a string `rule`, a non-empty `testGroups` array, each group an object with a
// `tolerance` object whose `abs` and `rel` are numbers >= 0 and a non-empty `tests` array, each
// test an object with an integer `tcId` >= 1, a `result` among valid / invalid / acceptable and an
// `expected`; `numberOfTests`, when present, equals the number of tests; golden::compose_input of
// every test returns an object or throws a pathref::Error. A broken invariant traps.
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

bool non_negative_number(const Json& o, const char* key) {
  const auto it = o.find(key);
  return it != o.end() && it->is_number() && it->get<double>() >= 0.0;
}

void check_tolerance(const Json& t) {
  if (!t.is_object() || !non_negative_number(t, "abs") || !non_negative_number(t, "rel")) __builtin_trap();
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace pathref;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  Json doc;
  try {
    doc = io::parse_json_text(text, "fuzz.json");
    golden::check_document_shape(doc, "fuzz.json", text);
  } catch (const ParseError& e) {
    for (const char c : std::string(e.what()))
      if (static_cast<unsigned char>(c) < 0x20) __builtin_trap();
    return 0;
  }
  if (!doc.is_object() || !doc.contains("rule") || !doc.at("rule").is_string()) __builtin_trap();
  const Json& groups = doc.at("testGroups");
  if (!groups.is_array() || groups.empty()) __builtin_trap();
  std::size_t count = 0;
  for (const Json& g : groups) {
    if (!g.is_object() || !g.contains("tolerance") || !g.contains("tests")) __builtin_trap();
    check_tolerance(g.at("tolerance"));
    const Json& tests = g.at("tests");
    if (!tests.is_array() || tests.empty()) __builtin_trap();
    for (const Json& t : tests) {
      ++count;
      if (!t.is_object() || !t.contains("tcId") || !t.contains("expected") || !t.contains("result")) __builtin_trap();
      const Json& id = t.at("tcId");
      if (!id.is_number_integer() || id.get<std::int64_t>() < 1) __builtin_trap();
      const Json& r = t.at("result");
      if (r != "valid" && r != "invalid" && r != "acceptable") __builtin_trap();
      if (t.contains("tolerance")) check_tolerance(t.at("tolerance"));
      try {
        const Json input = golden::compose_input(doc, g, t);
        if (!input.is_object()) __builtin_trap();
      } catch (const Error&) {
      }
    }
  }
  if (doc.contains("numberOfTests")) {
    const Json& n = doc.at("numberOfTests");
    if (!n.is_number_integer() || n.get<std::int64_t>() < 0 || static_cast<std::size_t>(n.get<std::int64_t>()) != count)
      __builtin_trap();
  }
  return 0;
}
