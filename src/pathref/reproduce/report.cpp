#include "pathref/reproduce/report.hpp"

#include <fmt/core.h>

#include <map>

namespace pathref::reproduce {

Json provenance_json(const Provenance& p) {
  return Json{{"command", p.command},
              {"build_type", p.build_type},
              {"date_utc", p.date_utc},
              {"machine", p.machine},
              {"pathref_version", p.pathref_version}};
}

Json claim_json(const Claim& c) {
  return Json{{"id", c.id},       {"text", c.text}, {"source", c.source},
              {"paper", c.paper}, {"ours", c.ours}, {"rule", c.rule},
              {"verdict", std::string(to_string(c.verdict))}, {"note", c.note}};
}

std::string md_number(const Json& v, int decimals) {
  if (!v.is_number()) return "—";
  return fixed(v.get<double>(), decimals);
}

const Json& at_or_null(const Json& doc, std::initializer_list<std::string_view> path) {
  static const Json null_json = nullptr;
  const Json* cur = &doc;
  for (const std::string_view key : path) {
    if (!cur->is_object()) return null_json;
    const auto it = cur->find(std::string(key));
    if (it == cur->end()) return null_json;
    cur = &*it;
  }
  return *cur;
}

std::string planner_label(std::string_view name) {
  static const std::map<std::string, std::string, std::less<>> labels = {
      {"ga", "GA"},
      {"aco", "ACO"},
      {"iaco-shi", "IACO"},
      {"iaco-shi-nomin", "IACO*"},
      {"iga-shi", "IGA"},
      {"iga-shi-nomax", "IGA*"},
      {"hybrid-ga-aco", "traditional hybrid"},
      {"iha", "IHA"},
      {"astar", "A*"},
      {"dijkstra", "Dijkstra"},
      {"iaco-han", "IACO-A* (iaco-han)"},
      {"astar-han", "A* (Han, Chebyshev)"},
  };
  const auto it = labels.find(name);
  return it == labels.end() ? std::string(name) : it->second;
}

std::string md_row(const std::vector<std::string>& cells) {
  std::string s = "|";
  for (const auto& c : cells) s += " " + c + " |";
  return s + "\n";
}

std::string md_claims(const Json& claims) {
  std::string s = md_row({"id", "claim", "source", "paper", "pathref", "verdict", "rule / note"});
  s += md_row({"---", "---", "---", "---", "---", "---", "---"});
  for (const Json& c : claims) {
    std::string verdict = c.at("verdict").get<std::string>();
    if (verdict == "holds") verdict = "**holds**";
    else if (verdict == "does not hold") verdict = "**does not hold**";
    std::string rule = c.at("rule").get<std::string>();
    const std::string note = c.at("note").get<std::string>();
    if (!note.empty()) rule += rule.empty() ? note : "; " + note;
    s += md_row({c.at("id").get<std::string>(), c.at("text").get<std::string>(),
                 c.at("source").get<std::string>(), c.at("paper").get<std::string>(),
                 c.at("ours").get<std::string>(), verdict, rule});
  }
  return s;
}

std::string md_verdict_summary(const Json& claims) {
  std::vector<std::string> ids[3];
  const char* names[3] = {"holds", "does not hold", "cannot be tested"};
  for (const Json& c : claims) {
    const auto v = c.at("verdict").get<std::string>();
    for (std::size_t k = 0; k < 3; ++k)
      if (v == names[k]) ids[k].push_back(c.at("id").get<std::string>());
  }
  std::string s = fmt::format("{} claims: {} hold, {} do not hold, {} cannot be tested.\n\n", claims.size(),
                              ids[0].size(), ids[1].size(), ids[2].size());
  for (std::size_t k = 0; k < 3; ++k) {
    std::string list;
    for (const auto& id : ids[k]) list += (list.empty() ? "" : ", ") + id;
    s += fmt::format("- {}: {}\n", names[k], list.empty() ? "—" : list);
  }
  return s;
}

std::string md_provenance(const Json& p, const std::string& out_name) {
  std::string s;
  s += fmt::format("- command: `{}`\n", p.value("command", ""));
  s += fmt::format("- pathref {}, build type {}\n", p.value("pathref_version", ""), p.value("build_type", ""));
  s += fmt::format("- date (UTC): {}\n", p.value("date_utc", ""));
  s += fmt::format("- machine: {}\n", p.value("machine", ""));
  if (p.contains("total_wall_s") && p.at("total_wall_s").is_number())
    s += fmt::format("- total wall-clock time of the reproduction: {} s\n",
                     fixed(p.at("total_wall_s").get<double>(), 1));
  s += fmt::format("- every number of this page, every parameter and every seed: `{}`\n", out_name);
  return s;
}

std::string md_results_table(const Json& results, const std::vector<std::string>& order,
                             const std::string& key) {
  std::string s = fmt::format("<!-- results:{} -->\n", key);
  s += md_row({"planner", "runs", "found", "valid", "best length", "mean length", "std length",
               "mean turns", "std turns", "min turns", "mean iter. to converge", "std iter.",
               "mean iter. (whole curve)", "mean drive time (s)", "mean wall time (ms)"});
  s += md_row({"---", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:",
               "---:", "---:", "---:", "---:"});
  for (const std::string& name : order) {
    const Json& r = at_or_null(results, {name});
    if (r.is_null() || !r.value("available", false)) {
      s += md_row({"`" + name + "`", "not available in this build", "", "", "", "", "", "", "", "",
                   "", "", "", "", ""});
      continue;
    }
    const Json& sm = r.at("summary");
    s += md_row({"`" + name + "`", std::to_string(sm.at("runs").get<std::int64_t>()),
                 std::to_string(sm.at("found").get<std::int64_t>()),
                 std::to_string(sm.at("valid").get<std::int64_t>()),
                 md_number(sm.at("length").at("min"), 4), md_number(sm.at("length").at("mean"), 4),
                 md_number(sm.at("length").at("std"), 4), md_number(sm.at("turns").at("mean"), 2),
                 md_number(sm.at("turns").at("std"), 2), md_number(sm.at("turns").at("min"), 0),
                 md_number(sm.at("converged_at").at("mean"), 2),
                 md_number(sm.at("converged_at").at("std"), 2),
                 md_number(sm.at("converged_at_whole_curve").at("mean"), 2),
                 md_number(sm.at("drive_time_s").at("mean"), 2),
                 md_number(sm.at("wall_ms").at("mean"), 1)});
  }
  return s;
}

}  // namespace pathref::reproduce
