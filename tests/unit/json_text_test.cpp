// JSON text with positions (spec/cli.md#exit-codes): every JSON reader reports bad input as a
// ParseError FILE:LINE:COLUMN, including a number too large for a double, which nlohmann reports
// as out_of_range 406 with no position. Regression: the fuzz smoke of 2026-12-02 found both the
// path-file reader (JSON lines) and the fused-scenario reader ending in std::terminate on it.
#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "pathref/core/error.hpp"
#include "pathref/io/input_file.hpp"
#include "pathref/io/json_reader.hpp"
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
  CHECK(m.find(": expected a number within the range of a double (number overflow parsing") != std::string::npos);
  CHECK(m.find("json.exception") == std::string::npos);  // no library text (issue 27, item 6)
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

// ------------------------------------------------------------------ issue 27: limits of the one reader

namespace {

std::string nested_arrays(std::size_t depth) { return std::string(depth, '[') + std::string(depth, ']'); }

template <class E, class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("json_text: nesting up to max_depth is accepted, one level more is refused at that bracket", "[io][json]") {
  using pathref::io::parse_json_text;
  CHECK(parse_json_text(nested_arrays(64), "d.json").is_array());
  const std::string m = parse_error_of([] { (void)parse_json_text(nested_arrays(65), "d.json"); });
  CHECK(m.rfind("d.json:1:65: expected JSON nested at most 64 levels deep", 0) == 0);
  // Objects count as arrays do; the offending '{' is found across lines and inside keys with brackets.
  std::string obj;
  for (int i = 0; i < 65; ++i) obj += "{\"[{\":\n";
  obj += "1";
  for (int i = 0; i < 65; ++i) obj += "}";
  const std::string mo = parse_error_of([&] { (void)parse_json_text(obj, "o.json"); });
  CHECK(mo.rfind("o.json:65:1: expected JSON nested at most 64 levels deep", 0) == 0);
  // A custom limit.
  pathref::io::JsonLimits three;
  three.max_depth = 3;
  CHECK_NOTHROW((void)parse_json_text("[[[1]]]", "t.json", 1, three));
  CHECK(parse_error_of([&] { (void)parse_json_text("[[[[1]]]]", "t.json", 1, three) ; }).rfind("t.json:1:4:", 0) == 0);
}

TEST_CASE("json_text: a 100000-deep document is refused before it is built (no stack overflow)", "[io][json]") {
  // Issue 27 item 1: conform, golden check, check --path, eval and --set crashed with SIGSEGV on
  // such values, because the value was built and later destroyed, compared or printed recursively.
  const std::string deep = nested_arrays(100000);
  const std::string m = parse_error_of([&] { (void)pathref::io::parse_json_text(deep, "deep.json"); });
  CHECK(m.rfind("deep.json:1:65:", 0) == 0);
  std::string deep_obj;
  for (int i = 0; i < 100000; ++i) deep_obj += "{\"a\":";
  CHECK(parse_error_of([&] { (void)pathref::io::parse_json_text(deep_obj, "o.json"); }).rfind("o.json:1:321:", 0) == 0);
}

TEST_CASE("json_text: a duplicate key is refused at its second occurrence", "[io][json]") {
  const std::string m = parse_error_of([] {
    (void)pathref::io::parse_json_text("{\"a\": 1,\n \"b\": {\"a\": 2, \"c\": 3},\n  \"a\": 4}", "k.json");
  });
  CHECK(m.rfind("k.json:3:3: expected an object with distinct keys (the key \"a\" appears twice)", 0) == 0);
  // The same key in two different objects is not a duplicate.
  CHECK_NOTHROW((void)pathref::io::parse_json_text("[{\"a\": 1}, {\"a\": 2}]", "k.json"));
}

TEST_CASE("json_text: a byte order mark is refused at 1:1", "[io][json]") {
  const std::string m = parse_error_of([] { (void)pathref::io::parse_json_text("\xEF\xBB\xBF{}", "b.json"); });
  CHECK(m.rfind("b.json:1:1: expected JSON text without a byte order mark", 0) == 0);
}

TEST_CASE("json_text: a text over max_bytes is refused before parsing", "[io][json]") {
  pathref::io::JsonLimits small;
  small.max_bytes = 10;
  CHECK_NOTHROW((void)pathref::io::parse_json_text("[1,2,3,4]", "s.json", 1, small));
  const std::string m = parse_error_of([&] { (void)pathref::io::parse_json_text("[1,2,3,4,5]", "s.json", 1, small); });
  CHECK(m.rfind("s.json:1:1: expected a JSON text of at most 10 bytes; this one has 11 bytes", 0) == 0);
}

TEST_CASE("json_text: messages carry no raw control or non-ASCII byte and no library prefix", "[io][json]") {
  const std::string m = parse_error_of([] { (void)pathref::io::parse_json_text(std::string("[tr\0\xff", 5), "n.json"); });
  CHECK(m.find("json.exception") == std::string::npos);
  CHECK(m.find("parse error at line") == std::string::npos);
  for (const char c : m) CHECK((static_cast<unsigned char>(c) >= 0x20 && static_cast<unsigned char>(c) < 0x7F));
  CHECK(pathref::io::printable(std::string("a\0b\xEF\xBB\xBF", 6)) == "a\\x00b\\xEF\\xBB\\xBF");
  CHECK(pathref::io::printable("abcdef", 3) == "abc...");
}

TEST_CASE("json_text: CLI values are JSON when they are JSON, strings when not, errors past a limit", "[io][json]") {
  using pathref::io::parse_cli_json_value;
  CHECK(parse_cli_json_value("1.5", "--set alpha")->get<double>() == 1.5);
  CHECK(parse_cli_json_value("[1, 2]", "--set alpha")->size() == 2);
  CHECK_FALSE(parse_cli_json_value("strict", "--set policy").has_value());
  CHECK_FALSE(parse_cli_json_value("[1, 2", "--set alpha").has_value());
  const std::string m = error_of<pathref::UsageError>([] { (void)parse_cli_json_value(nested_arrays(60000), "--set alpha"); });
  CHECK(m == "--set alpha: expected JSON nested at most 64 levels deep (arrays and objects) (at character 65 of the value)");
  // An unterminated deep value is refused for its depth, never taken as a string.
  CHECK_THROWS_AS((void)parse_cli_json_value(std::string(40000, '['), "x"), pathref::UsageError);
  CHECK_THROWS_AS((void)parse_cli_json_value("{\"a\":1,\"a\":2}", "x"), pathref::UsageError);
}

TEST_CASE("json_text: pointer_offset and json_error_at locate values", "[io][json]") {
  const std::string t = "{\n  \"a\": [10, {\"b~/c\": true}],\n  \"d\": \"x\"\n}";
  using pathref::io::pointer_offset;
  CHECK(pointer_offset(t, "") == 0);
  CHECK(t.substr(pointer_offset(t, "/a"), 3) == "[10");
  CHECK(t.substr(pointer_offset(t, "/a/0"), 2) == "10");
  CHECK(t.substr(pointer_offset(t, "/a/1/b~0~1c"), 4) == "true");
  CHECK(t.substr(pointer_offset(t, "/d"), 3) == "\"x\"");
  // A missing member is located at the deepest value on its way.
  CHECK(pointer_offset(t, "/a/7") == pointer_offset(t, "/a"));
  CHECK(pointer_offset(t, "/zz") == 0);
  const pathref::ParseError e = pathref::io::json_error_at(t, "p.json", "/a/1/b~0~1c", "expected a number");
  CHECK(std::string(e.what()) == "p.json:2:22: /a/1/b~0~1c: expected a number");
  CHECK(e.line() == 2);
  CHECK(e.column() == 22);
  // Without text (a value that came from no file): the pointer only.
  CHECK(std::string(pathref::io::json_error_at("", "<input>", "/w", "expected 1").what()) == "<input>: /w: expected 1");
  // pointer_offset is iterative: a pointer 60 levels deep into a 64-deep text.
  const std::string deep = nested_arrays(64);
  std::string ptr;
  for (int i = 0; i < 60; ++i) ptr += "/0";
  CHECK(pointer_offset(deep, ptr) == 60);
}

TEST_CASE("input_file: non-regular files are refused without blocking, with the reason", "[io][file]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("pathref_input_file_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  using pathref::io::read_input_file;
  using pathref::UsageError;
  CHECK(error_of<UsageError>([&] { (void)read_input_file(dir.string(), "data file", 100); })
            .find("it is a directory, not a regular file") != std::string::npos);
  CHECK(error_of<UsageError>([] { (void)read_input_file("/dev/zero", "data file", 100); })
            .find("cannot read data file '/dev/zero': it is a character device, not a regular file") != std::string::npos);
  const fs::path fifo = dir / "fifo";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  CHECK(error_of<UsageError>([&] { (void)read_input_file(fifo.string(), "data file", 100); })
            .find("it is a FIFO (named pipe), not a regular file") != std::string::npos);
  // A blocking open would never return (no writer): reaching the check above is the proof; ctest's
  // timeout bounds a regression.
  CHECK(error_of<UsageError>([&] { (void)read_input_file((dir / "missing").string(), "model file", 100); })
            .find("cannot read model file '" + (dir / "missing").string() + "': No such file or directory") != std::string::npos);
  const fs::path f = dir / "f.txt";
  std::ofstream(f) << "0123456789";
  CHECK(read_input_file(f.string(), "x", 10) == "0123456789");
  CHECK(error_of<UsageError>([&] { (void)read_input_file(f.string(), "x", 9); })
            .find("has 10 bytes, more than the limit of 9") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("json_reader: typed access names the file, line, column, pointer and what was expected", "[io][json]") {
  const std::string t = "{\"w\": -1, \"s\": 3, \"o\": {\"x\": 1}}";
  const nlohmann::json doc = pathref::io::parse_json_text(t, "r.json");
  const pathref::io::JsonReader rd("r.json", t);
  CHECK(error_of<pathref::ParseError>([&] { (void)rd.integer(doc.at("w"), "/w", 1, 10); }) ==
        "r.json:1:7: /w: expected an integer in [1, 10], got -1");
  CHECK(error_of<pathref::ParseError>([&] { (void)rd.string(doc.at("s"), "/s"); }) ==
        "r.json:1:16: /s: expected a string, got an integer");
  CHECK(error_of<pathref::ParseError>([&] { rd.keys(doc.at("o"), "/o", {"y"}); }) ==
        "r.json:1:30: /o/x: unknown key (expected one of: y)");
  CHECK(error_of<pathref::ParseError>([&] { (void)rd.need(doc, "", "z", "a number"); }) ==
        "r.json:1:1: /: missing key \"z\" (expected a number)");
}
