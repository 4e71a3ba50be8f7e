// JSON text with positions (spec/cli.md#exit-codes): every JSON reader reports bad input as a
// ParseError FILE:LINE:COLUMN, including a number too large for a double, which nlohmann reports
// as out_of_range 406 with no position. Regression: the fuzz smoke of 2026-12-02 found both the
// path-file reader (JSON lines) and the fused-scenario reader ending in std::terminate on it.
#include <catch2/catch.hpp>

#include <string>

#include "pathref/core/error.hpp"
#include "pathref/io/json_text.hpp"
#include "pathref/io/path_file.hpp"
#include "pathref/sim/fused.hpp"

namespace {

template <class F>
std::string parse_error_of(F&& f) {
  try {
    f();
  } catch (const pathref::ParseError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("json_text: a syntax error is a ParseError at its line and column", "[io][json]") {
  const std::string m = parse_error_of([] { (void)pathref::io::parse_json_text("{\"a\": 1,\n  ]", "x.json"); });
  CHECK(m.find("x.json:2:3:") != std::string::npos);
  CHECK(m.find(": expected valid JSON (") != std::string::npos);
}

TEST_CASE("json_text: a number that overflows a double is a ParseError with a position", "[io][json]") {
  const std::string m = parse_error_of([] { (void)pathref::io::parse_json_text("{\"a\":\n 1e999}", "x.json"); });
  CHECK(m.find("x.json:2:") != std::string::npos);
  CHECK(m.find(": expected valid JSON (number overflow parsing") != std::string::npos);  // nlohmann 406, without its prefix
  CHECK(m.find("406") == std::string::npos);
  // Within range, an ordinary number parses.
  CHECK(pathref::io::parse_json_text("{\"a\": 1e300}", "x.json").at("a").get<double>() == 1e300);
}

TEST_CASE("json_text: JSON-lines path files report the file's line for both kinds of error", "[io][json]") {
  using pathref::io::PathFormat;
  const std::string overflow = parse_error_of([] {
    (void)pathref::io::parse_path_text("[[0,0],[1,1]]\n\n[[0,0],[9e999,1]]\n", "p.jsonl", PathFormat::automatic, true);
  });
  CHECK(overflow.find("p.jsonl:3:") != std::string::npos);
  const std::string syntax = parse_error_of([] {
    (void)pathref::io::parse_path_text("[[0,0],[1,1]]\n[[0,0],[1,1\n", "p.jsonl", PathFormat::automatic, true);
  });
  CHECK(syntax.find("p.jsonl:2:") != std::string::npos);
  // The fuzz input (base64 ICAgOS4w…): a number with a quote and a NUL inside the exponent, single-file mode.
  const std::string fuzz("   9.0000000e+0021474836469.0000000e+'\0" "0\n   1/0000000e+01\n", 58);
  for (const bool lines : {false, true})
    for (const PathFormat f : {PathFormat::automatic, PathFormat::plan, PathFormat::xy, PathFormat::node, PathFormat::rowcol}) {
      try {
        (void)pathref::io::parse_path_text(fuzz, "fuzz.txt", f, lines);
      } catch (const pathref::ParseError&) {
      }
    }
}

TEST_CASE("json_text: the fused-scenario fuzz input is a ParseError", "[io][json]") {
  const std::string m = parse_error_of([] {
    (void)pathref::dwa::parse_fused_scenario("{\"e\x7frmat\": 155e5554[\".1.\"luati}", "fuzz.json", "/nonexistent");
  });
  CHECK(m.find("fuzz.json:1:") != std::string::npos);
}
