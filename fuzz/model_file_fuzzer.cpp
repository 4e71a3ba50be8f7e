// Fuzz target: model files of `pathref classify --model` (format pathref-ml-model version 1,
// spec/cin2021-ml.md#cli), read as the CLI reads them: io::parse_json_text then io::model_from_json.
//
// INVARIANT: for every byte string t, reading t either returns a Model or throws pathref::ParseError
// (never another exception, never UB, never a recursion deeper than the JSON layer's 64 levels); a
// ParseError's message holds no library exception text ("[json.exception", unless the input itself
// holds it: a message may quote the input) and no raw control
// byte. A returned model has 1..64 features and classes, writes back (ml::to_json) to a document
// that reads again to the same JSON, and predicts a class in [0, classes) for the all-zero and the
// all-one inputs. A broken invariant traps (__builtin_trap); sanitizers catch the rest.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathref/io/model_file.hpp"
#include "pathref/core/error.hpp"
#include "pathref/io/json_text.hpp"
#include "pathref/ml/classifier.hpp"

namespace {
void check_message(const std::string& m, std::string_view input) {
  if (m.find("[json.exception") != std::string::npos && input.find("[json.exception") == std::string_view::npos)
    __builtin_trap();
  for (const char c : m)
    if (static_cast<unsigned char>(c) < 0x20) __builtin_trap();
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace pathref;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  ml::Model m;
  try {
    m = io::model_from_json(io::parse_json_text(text, "fuzz.json"), "fuzz.json");
  } catch (const ParseError& e) {
    check_message(e.what(), text);
    return 0;
  }
  if (m.features < 1 || m.features > 64 || m.classes < 1 || m.classes > 64) __builtin_trap();
  const nlohmann::json once = io::to_json(m);
  const nlohmann::json twice = io::to_json(io::model_from_json(once, "back.json"));
  if (once != twice) __builtin_trap();
  for (const double v : {0.0, 1.0}) {
    const std::vector<double> x(m.features, v);
    const int c = ml::predict(m, x);
    if (c < 0 || static_cast<std::size_t>(c) >= m.classes) __builtin_trap();
  }
  return 0;
}
