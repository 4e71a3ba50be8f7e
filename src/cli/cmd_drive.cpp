// `pathref drive (--path FILE | stdin) --base mecanum|diff --cell SIZE [--svg FILE] [--json]`:
// the time to drive a grid path with a Mecanum or a differential-drive base, its wheel-speed
// schedule and speed profile. Spec: spec/mecanum.md (drive.path-time, section "CLI").
#include <fmt/core.h>

#include <cctype>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "pathref/io/input_file.hpp"
#include "pathref/io/json_text.hpp"
#include "pathref/core/error.hpp"
#include "pathref/grid/json_codec.hpp"
#include "pathref/io/svg.hpp"
#include "pathref/vehicle/drive.hpp"
#include "pathref/vehicle/mecanum.hpp"

namespace pathref::cli {

namespace {

using Json = nlohmann::json;

struct DriveOptions {
  std::string path_file;
  std::string base;
  double cell = 0.0;
  std::string svg_file;
  bool json = false;
  double wheel_radius = vehicle::Geometry{}.r;
  double lx = vehicle::Geometry{}.lx;
  double ly = vehicle::Geometry{}.ly;
  double rpm = vehicle::shi2022_rated_rpm;
  std::string limit_at = "output";
  double gear_ratio = vehicle::m2006_gear_ratio;
  double accel = vehicle::DriveParams{}.accel;
  double vmax = std::numeric_limits<double>::infinity();
  double corner_speed = 0.0;
  std::optional<double> half_track;  // default: ly
  double yaw_rate_max = std::numeric_limits<double>::infinity();
};

/// A path from JSON: an object with "path" (e.g. `pathref plan --json`) or a bare array of
/// [x, y]. nullopt when the object says found = false or holds no path (a plan that found none).
std::optional<std::vector<grid::Cell>> path_from_doc(const Json& doc, const std::string& source) {
  if (doc.is_array()) return grid::path_from_json(doc);
  if (!doc.is_object())
    throw UsageError(source + ": expected a JSON object with \"path\" or an array of [x, y]");
  if (doc.contains("found") && doc.at("found").is_boolean() && !doc.at("found").get<bool>())
    return std::nullopt;
  if (!doc.contains("path"))
    throw UsageError(source + ": the JSON object has no \"path\" (expected pathref plan --json output)");
  if (doc.at("path").is_null()) return std::nullopt;
  auto path = grid::path_from_json(doc.at("path"));
  if (path.empty()) return std::nullopt;
  return path;
}

/// Text: one cell "x y" or "x,y" per line; '#' starts a comment; blank lines are skipped.
std::vector<grid::Cell> path_from_text(const std::string& text, const std::string& source) {
  std::vector<grid::Cell> path;
  std::istringstream in(text);
  std::string line;
  std::size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    for (char& ch : line)
      if (ch == ',' || ch == '\t' || ch == '\r') ch = ' ';
    std::size_t pos = 0;
    std::vector<long long> values;
    while (true) {
      while (pos < line.size() && line[pos] == ' ') ++pos;
      if (pos >= line.size()) break;
      const std::size_t start = pos;
      if (line[pos] == '-' || line[pos] == '+') ++pos;
      while (pos < line.size() && std::isdigit(static_cast<unsigned char>(line[pos])) != 0) ++pos;
      const bool has_digits = pos > start && std::isdigit(static_cast<unsigned char>(line[pos - 1])) != 0;
      if (!has_digits || (pos < line.size() && line[pos] != ' ') || values.size() >= 2)
        throw ParseError(source, number, start + 1, "expected a cell as two integers 'x y'");
      try {
        values.push_back(std::stoll(line.substr(start, pos - start)));
      } catch (const std::out_of_range&) {
        throw ParseError(source, number, start + 1, "integer out of range");
      }
    }
    if (values.empty()) continue;
    if (values.size() != 2)
      throw ParseError(source, number, line.size() + 1, "expected a cell as two integers 'x y'");
    path.push_back(grid::Cell{values[0], values[1]});
  }
  return path;
}

/// Reads the path from `text` (JSON if it starts with '{' or '[', text otherwise).
std::optional<std::vector<grid::Cell>> read_path(const std::string& text, const std::string& source) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos)
    throw UsageError(source + " is empty: give --path FILE or pipe `pathref plan --json` into drive");
  if (text[first] == '{' || text[first] == '[') {
    return path_from_doc(io::parse_json_text(text, source), source);
  }
  auto path = path_from_text(text, source);
  if (path.empty()) return std::nullopt;
  return path;
}

std::string fmt_num(double v) {
  if (v == std::numeric_limits<double>::infinity()) return "inf";
  return fmt::format("{:.6g}", v);
}

Json num(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return v;
}

Json result_json(const DriveOptions& o, const vehicle::DriveParams& p, const vehicle::PathTime& pt,
                 const std::vector<vehicle::Knot>& ks, std::size_t cells) {
  Json runs = Json::array();
  for (const auto& r : pt.runs)
    runs.push_back(Json{{"dir", Json::array({r.run.dir.x, r.run.dir.y})},
                        {"steps", r.run.steps},
                        {"distance", r.distance},
                        {"v_limit", num(r.v_limit)},
                        {"a_limit", r.a_limit},
                        {"v_start", r.v_start},
                        {"v_peak", r.profile.v_peak},
                        {"v_end", r.v_end},
                        {"shape", r.profile.reaches_limit ? "trapezoid" : "triangle"},
                        {"time", r.profile.time}});
  Json joints = Json::array();
  for (const auto& j : pt.joints)
    joints.push_back(Json{{"angle", j.turn.angle}, {"sense", j.turn.sense}, {"time", j.profile.time}});
  Json sched = Json::array();
  for (const auto& k : ks) {
    Json rpm = Json::array();
    for (double w : k.wheels) rpm.push_back(vehicle::to_rpm(w));
    sched.push_back(Json{{"t", k.t}, {"vx", k.vx}, {"vy", k.vy}, {"omega", k.omega}, {"wheel_rpm", rpm}});
  }
  return Json{
      {"format", "pathref-drive"},
      {"format_version", 1},
      {"base", vehicle::to_string(pt.base)},
      {"cell", o.cell},
      {"cells", cells},
      {"params",
       Json{{"wheel_radius", p.geometry.r},
            {"lx", p.geometry.lx},
            {"ly", p.geometry.ly},
            {"rpm", o.rpm},
            {"limit_at", o.limit_at},
            {"gear_ratio", o.gear_ratio},
            {"w_max", p.wheel_speed_max},
            {"accel", p.accel},
            {"vmax", num(p.speed_cap)},
            {"corner_speed", p.corner_speed},
            {"half_track", p.half_track},
            {"yaw_rate_max", num(p.yaw_rate_cap)}}},
      {"time", pt.time},
      {"distance", pt.distance},
      {"turns", pt.turns},
      {"run_time", pt.run_time},
      {"rotate_time", pt.rotate_time},
      {"runs", runs},
      {"joints", joints},
      {"schedule", sched}};
}

void print_report(const DriveOptions& o, const vehicle::DriveParams& p, const vehicle::PathTime& pt,
                  const std::vector<vehicle::Knot>& ks, std::size_t cells) {
  const bool mec = pt.base == vehicle::Base::mecanum;
  fmt::print("pathref drive: {} base, {} cells, {} runs, {} turns, cell {} m\n",
             vehicle::to_string(pt.base), cells, pt.runs.size(), pt.turns, fmt_num(o.cell));
  fmt::print("vehicle: r = {} m, lx = {} m, ly = {} m; wheel limit {} rpm at the {} = {} rad/s at the wheel\n",
             fmt_num(p.geometry.r), fmt_num(p.geometry.lx), fmt_num(p.geometry.ly), fmt_num(o.rpm),
             o.limit_at == "output" ? "output shaft" : fmt::format("rotor (gear {}:1)", fmt_num(o.gear_ratio)),
             fmt_num(p.wheel_speed_max));
  if (mec)
    fmt::print("limits: a = {} m/s^2 at each wheel rim, v_max = {} m/s, corner speed {} m/s\n",
               fmt_num(p.accel), fmt_num(p.speed_cap), fmt_num(p.corner_speed));
  else
    fmt::print("limits: a = {} m/s^2 at each wheel rim, v_max = {} m/s, half track b = {} m, "
               "yaw rate {} rad/s, yaw acceleration {} rad/s^2\n",
               fmt_num(p.accel), fmt_num(p.speed_cap), fmt_num(p.half_track),
               fmt_num(pt.yaw_rate_limit), fmt_num(pt.yaw_accel_limit));
  fmt::print("\nrun  dir      steps  distance[m]  V[m/s]    A[m/s^2]  v_in      v_peak    v_out     time[s]\n");
  for (std::size_t j = 0; j < pt.runs.size(); ++j) {
    const auto& r = pt.runs[j];
    fmt::print("{:<4} {:<8} {:<6} {:<12.6f} {:<9.4f} {:<9.4f} {:<9.4f} {:<9.4f} {:<9.4f} {:.6f}\n", j + 1,
               fmt::format("({},{})", r.run.dir.x, r.run.dir.y), r.run.steps, r.distance, r.v_limit,
               r.a_limit, r.v_start, r.profile.v_peak, r.v_end, r.profile.time);
    if (!mec && j < pt.joints.size())
      fmt::print("     rotate {} {:.4f} rad on the spot{:>49.6f}\n", pt.joints[j].turn.sense > 0 ? "left " : "right",
                 pt.joints[j].turn.angle, pt.joints[j].profile.time);
  }
  fmt::print("\nwheel-speed schedule (piecewise linear between rows; wheel speeds in rpm at the wheel, + drives forward)\n");
  if (mec)
    fmt::print("{:>10} {:>9} {:>9} {:>11} {:>9} {:>9} {:>9} {:>9}\n", "t[s]", "vx[m/s]", "vy[m/s]",
               "omega[r/s]", "FL", "FR", "RL", "RR");
  else
    fmt::print("{:>10} {:>9} {:>9} {:>11} {:>9} {:>9}\n", "t[s]", "v[m/s]", "", "omega[r/s]", "left",
               "right");
  for (const auto& k : ks) {
    std::string line = fmt::format("{:>10.4f} {:>9.4f} {:>9} {:>11.4f}", k.t, k.vx,
                                   mec ? fmt::format("{:.4f}", k.vy) : std::string(), k.omega);
    for (double w : k.wheels) line += fmt::format(" {:>9.2f}", vehicle::to_rpm(w));
    fmt::print("{}\n", line);
  }
  fmt::print("\ndistance: {:.6f} m\n", pt.distance);
  fmt::print("turns: {}\n", pt.turns);
  if (!mec) fmt::print("run time: {:.6f} s, rotation time: {:.6f} s\n", pt.run_time, pt.rotate_time);
  fmt::print("time: {:.6f} s\n", pt.time);
}

std::string profile_svg(const vehicle::PathTime& pt, const std::vector<vehicle::Knot>& ks) {
  io::Series speed{"body speed [m/s]", {}, {}};
  io::Series yaw{"yaw rate [rad/s]", {}, {}};
  for (const auto& k : ks) {
    speed.x.push_back(k.t);
    speed.y.push_back(k.speed);
    yaw.x.push_back(k.t);
    yaw.y.push_back(k.omega);
  }
  std::vector<io::Series> series{speed};
  if (pt.base == vehicle::Base::diff) series.push_back(yaw);
  io::ChartOptions opt;
  opt.title = fmt::format("pathref drive: {} base, {:.3f} s, {:.3f} m, {} turns",
                          vehicle::to_string(pt.base), pt.time, pt.distance, pt.turns);
  opt.x_label = "time [s]";
  opt.y_label = pt.base == vehicle::Base::diff ? "speed [m/s], yaw rate [rad/s]" : "speed [m/s]";
  return io::svg_line_chart(series, opt);
}

int run_drive(const DriveOptions& o) {
  std::string text;
  std::string source;
  if (!o.path_file.empty()) {
    text = io::read_input_file(o.path_file, "path file", std::uintmax_t{1} << 30);  // as read_text_file
    source = o.path_file;
  } else {
    text.assign(std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>());
    source = "<stdin>";
  }
  const auto path = read_path(text, source);
  if (!path) {
    fmt::print(stderr, "pathref: {} holds no path to drive (the plan found none)\n", source);
    return 1;
  }
  vehicle::DriveParams p;
  p.geometry = vehicle::Geometry{o.wheel_radius, o.lx, o.ly};
  p.wheel_speed_max = vehicle::wheel_speed_limit(o.rpm, vehicle::parse_limit_at(o.limit_at), o.gear_ratio);
  p.accel = o.accel;
  p.speed_cap = o.vmax;
  p.corner_speed = o.corner_speed;
  p.half_track = o.half_track.value_or(o.ly);
  p.yaw_rate_cap = o.yaw_rate_max;
  const auto base = vehicle::parse_base(o.base);
  const vehicle::PathTime pt = vehicle::path_time(*path, o.cell, base, p);
  const auto ks = vehicle::schedule(pt, p);
  if (o.json) {
    Json doc = result_json(o, p, pt, ks, path->size());
    stamp_version(doc);
    fmt::print("{}\n", doc.dump(2));
  } else {
    print_report(o, p, pt, ks, path->size());
  }
  if (!o.svg_file.empty()) {
    write_figure(o.svg_file, profile_svg(pt, ks));
    if (!o.json) fmt::print("wrote {}\n", o.svg_file);
  }
  return 0;
}

}  // namespace

void add_drive_command(CLI::App& app, Action& run) {
  auto* cmd = app.add_subcommand(
      "drive",
      "Time to drive a grid path with a Mecanum or differential-drive base: wheel-speed schedule, "
      "total time, speed profile (spec/mecanum.md). Reads --path FILE or a `pathref plan --json` "
      "object on stdin");
  static DriveOptions o;
  cmd->add_option("--path", o.path_file,
                  "path file: JSON ({\"path\": [[x,y],...]} or [[x,y],...]) or text, one 'x y' per line; "
                  "default: JSON on stdin")
      ->type_name("FILE");
  cmd->add_option("--base", o.base, "mecanum (translates, never rotates) | diff (rotates on the spot at turns)")
      ->required()
      ->check(CLI::IsMember({"mecanum", "diff"}));
  cmd->add_option("--cell", o.cell, "cell size, m (> 0)")->required()->type_name("SIZE");
  cmd->add_option("--svg", o.svg_file, "draw the speed profile to FILE")->type_name("FILE");
  cmd->add_flag("--json", o.json, "print one JSON object instead of the report");
  cmd->add_option("--wheel-radius", o.wheel_radius, "wheel radius r, m (assumption)")->capture_default_str();
  cmd->add_option("--lx", o.lx, "half wheelbase, m (assumption)")->capture_default_str();
  cmd->add_option("--ly", o.ly, "half track, m (assumption)")->capture_default_str();
  cmd->add_option("--rpm", o.rpm, "rated wheel motor speed, rpm (Shi 2022 Table 2)")->capture_default_str();
  cmd->add_option("--limit-at", o.limit_at, "where --rpm is stated: output (gearbox output = wheel) | rotor")
      ->check(CLI::IsMember({"output", "rotor"}))
      ->capture_default_str();
  cmd->add_option("--gear-ratio", o.gear_ratio, "rotor : wheel speed ratio for --limit-at rotor (M2006: 36)")
      ->capture_default_str();
  cmd->add_option("--accel", o.accel, "acceleration limit at each wheel rim, m/s^2 (assumption)")
      ->capture_default_str();
  cmd->add_option("--vmax", o.vmax, "body speed cap, m/s (default inf: wheel limit only)");
  cmd->add_option("--corner-speed", o.corner_speed, "Mecanum speed through each turn, m/s (0: stop)")
      ->capture_default_str();
  cmd->add_option("--half-track", o.half_track, "differential-drive half track b, m (default: --ly)");
  cmd->add_option("--yaw-rate-max", o.yaw_rate_max, "differential-drive yaw-rate cap, rad/s (default inf)");
  cmd->callback([&run] { run = [] { return run_drive(o); }; });
}

}  // namespace pathref::cli
