// Properties of the pathref-grid 1 reader/writer (spec/formats.md#pathref-grid-1).
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/io/grid_text.hpp"
#include "support/generators.hpp"

using pathref::grid::Cell;
using pathref::grid::Grid;
using pathref::io::MapFile;
using pathref::io::parse_grid_text;
using pathref::io::to_grid_text;

namespace pathref::io {
/// Counterexamples print as their pathref-grid text (found by ADL).
void showValue(const MapFile& m, std::ostream& os);
void showValue(const MapFile& m, std::ostream& os) {
  os << "name '" << m.name << "'\n";
  if (m.start) os << "start " << m.start->x << " " << m.start->y << "\n";
  if (m.goal) os << "goal " << m.goal->x << " " << m.goal->y << "\n";
  for (const auto& row : m.grid.to_rows_top_first()) os << row << "\n";
}
}  // namespace pathref::io

namespace {

/// Either no cell or a free cell of g drawn uniformly among the free cells.
rc::Gen<std::optional<Cell>> gen_free_cell_or_none(const Grid& g) {
  std::vector<Cell> free;
  for (std::int64_t y = 0; y < g.height(); ++y)
    for (std::int64_t x = 0; x < g.width(); ++x)
      if (g.free(Cell{x, y})) free.push_back(Cell{x, y});
  if (free.empty()) return rc::gen::just(std::optional<Cell>{});
  return rc::gen::oneOf(rc::gen::just(std::optional<Cell>{}),
                        rc::gen::map(rc::gen::elementOf(free), [](Cell c) { return std::optional<Cell>(c); }));
}

/// A name the writer accepts: printable ASCII and some UTF-8, no leading/trailing space.
rc::Gen<std::string> gen_name() {
  return rc::gen::map(
      rc::gen::container<std::vector<int>>(rc::gen::inRange(0, 70)), [](const std::vector<int>& picks) {
        static const std::vector<std::string> alphabet = [] {
          std::vector<std::string> a;
          for (char c = 'a'; c <= 'z'; ++c) a.emplace_back(1, c);
          for (char c = '0'; c <= '9'; ++c) a.emplace_back(1, c);
          for (const char* s : {" ", "#", ".", "-", "_", "/", "\xC3\xA9", "\xE2\x86\x92"}) a.emplace_back(s);
          return a;
        }();
        std::string s;
        for (const int p : picks) s += alphabet[static_cast<std::size_t>(p) % alphabet.size()];
        while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.erase(s.begin());
        while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.pop_back();
        return s;
      });
}

rc::Gen<MapFile> gen_map_file() {
  return rc::gen::mapcat(pathref::testing::gen_grid(30, 30, 0.6), [](const Grid& g) {
    return rc::gen::apply(
        [g](std::optional<Cell> s, std::optional<Cell> t, std::string name) {
          if (s && t && *s == *t) t.reset();  // a map's start and goal differ (spec formats.md)
          return MapFile{g, s, t, std::move(name)};
        },
        gen_free_cell_or_none(g), gen_free_cell_or_none(g), gen_name());
  });
}

/// LF -> CRLF everywhere.
std::string to_crlf(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '\n') out += '\r';
    out += c;
  }
  return out;
}

}  // namespace

TEST_CASE("grid-text prop: write then read gives the same map", "[grid_text][prop]") {
  rc::prop("parse(to_grid_text(m)) == m", [] {
    const MapFile m = *gen_map_file();
    const std::string text = to_grid_text(m);
    const MapFile back = parse_grid_text(text, "rt");
    RC_ASSERT(back == m);
    RC_ASSERT(to_grid_text(back) == text);  // the writer's form is canonical
  });
}

TEST_CASE("grid-text prop: CRLF, comments and blank lines do not change the map", "[grid_text][prop]") {
  rc::prop("decorated text parses to the same map", [] {
    const MapFile m = *gen_map_file();
    const std::string text = to_grid_text(m);
    RC_ASSERT(parse_grid_text(to_crlf(text), "crlf") == m);
    // Insert a comment and a blank line after the magic line, and trailing blank lines.
    const auto nl = text.find('\n');
    const std::string decorated =
        text.substr(0, nl + 1) + "# comment ## with #\n\n \t\n" + text.substr(nl + 1) + "\n  \n";
    RC_ASSERT(parse_grid_text(decorated, "decorated") == m);
  });
}

TEST_CASE("grid-text prop: corrupted or truncated text parses or throws ParseError, nothing else",
          "[grid_text][prop]") {
  rc::prop("one byte changed or the text cut", [] {
    const MapFile m = *gen_map_file();
    const std::string text = to_grid_text(m);
    std::string bad = text;
    const auto pos = *rc::gen::inRange<std::size_t>(0, text.size());
    if (*rc::gen::arbitrary<bool>())
      bad[pos] = *rc::gen::elementOf(std::string(".# \t\r\n0123456789x-"));
    else
      bad.resize(pos);
    std::size_t lines = 1;
    for (const char c : bad) lines += c == '\n' ? 1 : 0;
    try {
      const MapFile back = parse_grid_text(bad, "bad");
      RC_ASSERT(back.grid.width() >= 1);
    } catch (const pathref::ParseError& e) {
      RC_ASSERT(e.file() == "bad");
      RC_ASSERT(e.line() >= 1);
      RC_ASSERT(e.line() <= lines + 1);
      RC_ASSERT(e.column() >= 1);
    }
  });
}
