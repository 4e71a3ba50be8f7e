// The plotting layer. Spec: spec/figures.md.
#include "pathref/io/plot.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "pathref/core/error.hpp"

namespace pathref::io::plot {

std::size_t glyphs(std::string_view utf8) {
  std::size_t n = 0;
  for (const char c : utf8)
    if ((static_cast<unsigned char>(c) & 0xC0U) != 0x80U) ++n;  // count lead bytes only
  return n;
}

double text_width(std::string_view text, double size) {
  return static_cast<double>(glyphs(text)) * size * kCharEm;
}

std::vector<std::string> wrap(std::string_view text, double size, double max_width) {
  const auto per_line = std::max<std::size_t>(1, static_cast<std::size_t>(max_width / (size * kCharEm)));
  std::vector<std::string> lines;
  std::string line;
  std::size_t line_n = 0;
  auto flush = [&] {
    if (!line.empty()) lines.push_back(line);
    line.clear();
    line_n = 0;
  };
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && text[i] == ' ') ++i;
    std::size_t j = i;
    while (j < text.size() && text[j] != ' ') ++j;
    if (j == i) break;
    std::string_view word = text.substr(i, j - i);
    i = j;
    std::size_t wn = glyphs(word);
    if (line_n > 0 && line_n + 1 + wn <= per_line) {
      line += ' ';
      line += word;
      line_n += 1 + wn;
      continue;
    }
    flush();
    while (wn > per_line) {  // a word longer than a line: cut it between characters
      std::size_t k = 0, taken = 0;
      while (k < word.size() && taken < per_line) {
        ++k;
        while (k < word.size() && (static_cast<unsigned char>(word[k]) & 0xC0U) == 0x80U) ++k;
        ++taken;
      }
      lines.emplace_back(word.substr(0, k));
      word = word.substr(k);
      wn -= taken;
    }
    line = std::string(word);
    line_n = wn;
  }
  flush();
  return lines;
}

std::string strip_paths(std::string_view text) {
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t j = std::min(text.find(' ', i), text.size());
    std::string_view word = text.substr(i, j - i);
    const auto slash = word.find_last_of('/');
    if (slash != std::string_view::npos && slash + 1 < word.size()) {
      // a path: starts at a root or a dot folder, has two or more slashes, or ends in a file name
      // with an extension ("maps/a.map"); "1/d" and "km/h" are not paths
      const std::string_view last = word.substr(slash + 1);
      const bool path_like = word.front() == '/' || word.substr(0, 2) == "./" || word.substr(0, 3) == "../" ||
                             std::count(word.begin(), word.end(), '/') >= 2 ||
                             (last.find('.') != std::string_view::npos && last.find('.') + 1 < last.size());
      if (path_like) word = last;
    }
    out += word;
    if (j < text.size()) out += ' ';
    i = j + 1;
  }
  return out;
}

std::string num(double v) { return fmt::format("{:.2f}", v); }

std::string escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

const char* colour(std::size_t i) {
  // Okabe & Ito (2008), "Color Universal Design": blue, vermillion, bluish green, orange,
  // reddish purple, sky blue, yellow (last: weak on white).
  static constexpr std::array<const char*, 7> kCycle = {kBlue, kVermillion, kGreen, kOrange,
                                                        kPurple, kSky, "#B8A800"};
  return kCycle[i % kCycle.size()];
}

const char* dash(std::size_t i) {
  static constexpr std::array<const char*, 6> kDash = {"", "8 4", "2 3", "8 3 2 3", "12 3", "4 2 1 2"};
  return kDash[i % kDash.size()];
}

std::string text(double x, double y, std::string_view s, double size, std::string_view anchor,
                 std::string_view cls, std::string_view fill) {
  return fmt::format("<text{}{} x=\"{}\" y=\"{}\" font-size=\"{}\"{}>{}</text>\n",
                     cls.empty() ? "" : fmt::format(" class=\"{}\"", cls),
                     fill.empty() ? "" : fmt::format(" fill=\"{}\"", fill), num(x), num(y), size,
                     anchor == "start" ? "" : fmt::format(" text-anchor=\"{}\"", anchor), escape(s));
}

std::string polyline(const std::vector<std::pair<double, double>>& pts, std::string_view cls,
                     std::string_view stroke, double width, std::string_view dasharray,
                     std::string_view extra) {
  std::string p;
  for (const auto& [x, y] : pts) {
    if (!p.empty()) p += ' ';
    p += num(x) + "," + num(y);
  }
  return fmt::format("<polyline class=\"{}\"{} points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{}\" "
                     "stroke-linejoin=\"round\" stroke-linecap=\"round\"{}/>\n",
                     cls, extra, p, stroke, num(width),
                     dasharray.empty() ? "" : fmt::format(" stroke-dasharray=\"{}\"", dasharray));
}

bool Box::overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
bool Box::inside(const Box& o) const { return x0 >= o.x0 && x1 <= o.x1 && y0 >= o.y0 && y1 <= o.y1; }

// ---- scales ---------------------------------------------------------------------------------

double Scale::map(double v, double p0, double p1) const {
  const double t = log ? (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo)) : (v - lo) / (hi - lo);
  return p0 + t * (p1 - p0);
}

std::string Scale::label(double v) const {
  if (log) return fmt::format("{:g}", v);
  return fmt::format("{:.{}f}", v, decimals);
}

Scale linear_scale(double lo, double hi, bool pad) {
  if (!(hi > lo)) {  // a single value: widen symmetrically so it sits mid-range
    const double w = lo == 0.0 ? 1.0 : std::abs(lo) * 0.1;
    lo -= w;
    hi += w;
  } else if (pad) {
    const double w = 0.05 * (hi - lo);
    lo -= w;
    hi += w;
  }
  const double raw = (hi - lo) / 5.0;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double norm = raw / mag;
  const double step = (norm <= 1.0 ? 1.0 : norm <= 2.0 ? 2.0 : norm <= 5.0 ? 5.0 : 10.0) * mag;
  Scale s;
  s.decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
  if (pad) {  // widened outwards to whole steps
    const double first = std::floor(lo / step) * step;
    const int count = static_cast<int>(std::lround((std::ceil(hi / step) * step - first) / step)) + 1;
    for (int i = 0; i < count; ++i) s.ticks.push_back(first + step * i);
    s.lo = s.ticks.front();
    s.hi = s.ticks.back();
  } else {  // exactly [lo, hi], ticks at the whole steps inside
    s.lo = lo;
    s.hi = hi;
    const double first = std::ceil(lo / step - 1e-9) * step;
    for (int i = 0; first + step * i <= hi + 1e-9 * step; ++i) s.ticks.push_back(first + step * i);
  }
  return s;
}

Scale log_scale(double lo, double hi) {
  require(lo > 0.0 && hi >= lo, "log_scale: range must be positive");
  Scale s;
  s.log = true;
  const double a = std::floor(std::log10(lo) + 1e-12);
  const double b = std::max(a + 1.0, std::ceil(std::log10(hi) - 1e-12));
  s.lo = std::pow(10.0, a);
  s.hi = std::pow(10.0, b);
  const bool fine = b - a <= 2.0;
  for (double e = a; e <= b + 0.5; e += 1.0) {
    const double d = std::pow(10.0, e);
    s.ticks.push_back(d);
    if (fine && e < b) {
      s.ticks.push_back(2.0 * d);
      s.ticks.push_back(5.0 * d);
    }
  }
  std::sort(s.ticks.begin(), s.ticks.end());
  return s;
}

bool wants_log(double lo, double hi) { return lo > 0.0 && std::isfinite(hi) && hi >= 20.0 * lo; }

// ---- labels ---------------------------------------------------------------------------------

std::string LabelPlacer::place(double x, double y, std::string_view label, double gap,
                               std::string_view cls, std::string_view fill, double size) {
  const double w = text_width(label, size);
  const double asc = 0.76 * size, desc = 0.24 * size;
  for (const double g : {gap, gap + 0.7 * size}) {  // the nearer ring of positions first
    // candidate baselines (x is the start of the text)
    const std::array<std::pair<double, double>, 6> cand = {{{x + g, y - g},
                                                            {x + g, y + g + asc},
                                                            {x - g - w, y - g},
                                                            {x - g - w, y + g + asc},
                                                            {x - w / 2.0, y - g - desc},
                                                            {x - w / 2.0, y + g + asc}}};
    for (const auto& [tx, ty] : cand) {
      const Box b{tx, ty - asc, tx + w, ty + desc};
      if (!b.inside(canvas_)) continue;
      if (std::any_of(taken_.begin(), taken_.end(), [&](const Box& t) { return t.overlaps(b); })) continue;
      taken_.push_back(b);
      return text(tx, ty, label, size, "start", cls, fill);
    }
  }
  return "";
}

// ---- frame ----------------------------------------------------------------------------------

Frame fit_frame(double x0, double y0, double x1, double y1, double left, double top, double w,
                double max_h, double max_scale) {
  require(x0 < x1 && y0 < y1, "fit_frame: empty world box");
  const double scale = std::min({max_scale, w / (x1 - x0), max_h / (y1 - y0)});
  Frame f{x0, y0, x1, y1, left, top, scale};
  f.left = left + (w - f.width()) / 2.0;  // centred horizontally
  return f;
}

double mark_step(double end_t, double max_marks) {
  for (double mag = 1.0;; mag *= 10.0)
    for (const double m : {1.0, 2.0, 5.0})
      if (end_t / (m * mag) <= max_marks) return m * mag;
}

std::vector<std::pair<std::size_t, double>> mark_samples(const std::vector<double>& times, double step) {
  std::vector<std::pair<std::size_t, double>> out;
  std::int64_t next = 0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (times[i] + 1e-9 < static_cast<double>(next) * step) continue;
    out.emplace_back(i, static_cast<double>(next) * step);
    while (times[i] + 1e-9 >= static_cast<double>(next) * step) ++next;
  }
  return out;
}

std::string time_marks(const std::vector<std::pair<double, double>>& pts, const std::vector<double>& times,
                       std::string_view cls, std::string_view colour, LabelPlacer& placer, std::string& labels) {
  std::string out;
  for (std::size_t k = 0; k < pts.size();) {
    std::size_t j = k + 1;
    while (j < pts.size() && pts[j] == pts[k]) ++j;
    const std::string label =
        j == k + 1 ? fmt::format("{:g}", times[k]) : fmt::format("{:g}-{:g}", times[k], times[j - 1]);
    const auto [x, y] = pts[k];
    out += fmt::format("<circle class=\"{}\" cx=\"{}\" cy=\"{}\" r=\"2.5\" fill=\"{}\"/>\n", cls, num(x), num(y), colour);
    placer.reserve(Box{x - 2.5, y - 2.5, x + 2.5, y + 2.5});
    labels += placer.place(x, y, label, 3.0, std::string(cls) + "-label", colour);
    k = j;
  }
  return out;
}

void Extent::add(double x, double y, double r) {
  if (!std::isfinite(x) || !std::isfinite(y)) return;
  if (empty) {
    x0 = x - r, y0 = y - r, x1 = x + r, y1 = y + r;
    empty = false;
    return;
  }
  x0 = std::min(x0, x - r);
  y0 = std::min(y0, y - r);
  x1 = std::max(x1, x + r);
  y1 = std::max(y1, y + r);
}

std::string obstacle_cells(const grid::Grid& g, const Frame& f) {
  std::string out;
  for (std::int64_t y = g.height() - 1; y >= 0; --y)
    for (std::int64_t x = 0; x < g.width(); ++x)
      if (g.blocked(grid::Cell{x, y}))
        out += fmt::format("<rect class=\"obstacle\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"black\"/>\n",
                           num(f.X(static_cast<double>(x))), num(f.Y(static_cast<double>(y) + 1.0)), num(f.scale),
                           num(f.scale));
  return out;
}

// ---- figure ---------------------------------------------------------------------------------

void Figure::title(std::string_view t) {
  const std::string clean = strip_paths(t);
  for (const auto& line : wrap(clean, kTitleFont, inner_width())) {
    y_ += kTitleFont;
    body_ += text(inner_left(), y_, line, kTitleFont, "start", "title");
    y_ += (kLineEm - 1.0) * kTitleFont;
  }
  y_ += 4.0;
}

std::string swatch(const LegendEntry& e, double x, double y) {
  const std::string c = e.absent ? std::string(kGrey) : e.colour;
  const double cx = x + 14.0, cy = y + 7.0;
  switch (e.kind) {
    case Swatch::line:
      return fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{}\" stroke-width=\"3\"{}/>",
                         num(x), num(cy), num(x + 28.0), num(cy), c,
                         e.absent ? " stroke-dasharray=\"1 3\""
                                  : (e.dasharray.empty() ? std::string() : fmt::format(" stroke-dasharray=\"{}\"", e.dasharray)));
    case Swatch::square:
      return fmt::format("<rect x=\"{}\" y=\"{}\" width=\"14\" height=\"14\" fill=\"{}\"/>", num(cx - 7.0), num(y), c);
    case Swatch::box:
      return fmt::format("<rect x=\"{}\" y=\"{}\" width=\"10\" height=\"10\" fill=\"none\" stroke=\"{}\" stroke-width=\"1.5\"/>",
                         num(cx - 5.0), num(y + 2.0), c);
    case Swatch::dot:
      return fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"6\" fill=\"{}\" stroke=\"black\"/>", num(cx), num(cy), c);
    case Swatch::ring:
      return fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"6\" fill=\"none\" stroke=\"{}\" stroke-width=\"2\"/>", num(cx),
                         num(cy), c);
    case Swatch::triangle:
      return fmt::format("<polygon points=\"{},{} {},{} {},{}\" fill=\"{}\"/>", num(cx), num(y), num(cx - 7.0),
                         num(y + 14.0), num(cx + 7.0), num(y + 14.0), c);
    case Swatch::cross:
      return fmt::format("<path d=\"M{} {}L{} {}M{} {}L{} {}\" stroke=\"{}\" stroke-width=\"2.5\"/>", num(cx - 6.0),
                         num(y + 1.0), num(cx + 6.0), num(y + 13.0), num(cx + 6.0), num(y + 1.0), num(cx - 6.0),
                         num(y + 13.0), c);
  }
  return "";
}

void Figure::legend(const std::vector<LegendEntry>& entries) {
  if (entries.empty()) return;
  constexpr double kSw = 28.0, kGap = 6.0, kSep = 16.0;
  const double row_h = kLineEm * kFont;
  const double avail = inner_width();
  std::string g = "<g class=\"legend\">\n";
  double x = inner_left();
  double top = y_ + 4.0;  // top of the current row
  double row_bottom = top + row_h;
  for (const auto& e : entries) {
    const double text_w = text_width(e.label);
    const double need = kSw + kGap + text_w;
    if (x > inner_left() && x + need > inner_left() + avail) {  // next row
      x = inner_left();
      top = row_bottom;
      row_bottom = top + row_h;
    }
    const auto lines = wrap(e.label, kFont, avail - kSw - kGap);
    g += swatch(e, x, top + (row_h - 14.0) / 2.0);
    double w = 0.0;
    for (std::size_t k = 0; k < lines.size(); ++k) {
      g += text(x + kSw + kGap, top + (row_h - 14.0) / 2.0 + 12.0 + row_h * static_cast<double>(k), lines[k]);
      w = std::max(w, text_width(lines[k]));
    }
    row_bottom = std::max(row_bottom, top + row_h * static_cast<double>(std::max<std::size_t>(1, lines.size())));
    x += kSw + kGap + w + kSep;
  }
  g += "</g>\n";
  body_ += g;
  y_ = row_bottom + 2.0;
}

void Figure::caption(std::string_view t, std::string_view cls) {
  for (const auto& line : wrap(t, kFont, inner_width())) {
    y_ += kFont;
    body_ += text(inner_left(), y_, line, kFont, "start", cls);
    y_ += (kLineEm - 1.0) * kFont;
  }
}

void Figure::block(std::string_view elements, double height) {
  body_ += elements;
  y_ += height;
}

std::string Figure::svg() const {
  const double h = y_ + kMargin;
  return fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"{0}\" height=\"{1}\" "
      "viewBox=\"0 0 {0} {1}\" font-family=\"{2}\">\n"
      "<rect class=\"background\" x=\"0\" y=\"0\" width=\"{0}\" height=\"{1}\" fill=\"white\"/>\n"
      "{3}</svg>\n",
      num(width_), num(h), kFontStack, body_);
}

}  // namespace pathref::io::plot
