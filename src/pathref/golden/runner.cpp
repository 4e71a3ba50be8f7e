#include "pathref/golden/runner.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "pathref/core/error.hpp"
#include "pathref/io/json_text.hpp"
#include "pathref/io/map_file.hpp"
#include "pathref/rules/registry.hpp"

namespace pathref::golden {

namespace fs = std::filesystem;

std::size_t Report::count(Status s) const {
  return static_cast<std::size_t>(
      std::count_if(cases.begin(), cases.end(), [s](const CaseResult& c) { return c.status == s; }));
}

Json compose_input(const Json& doc, const Json& group, const Json& test) {
  Json input = Json::object();
  if (group.contains("params")) input.update(group.at("params"));
  if (test.contains("input")) input.update(test.at("input"));
  if (test.contains("interpretation")) {
    for (const auto& [note, option] : test.at("interpretation").items()) {
      const Json& notes = doc.at("notes");
      if (!notes.contains(note) || !notes.at(note).contains("param"))
        throw UsageError("interpretation names note '" + note + "', which has no 'param'");
      input[notes.at(note).at("param").get<std::string>()] = option;
    }
  }
  return input;
}

namespace {

bool is_special_string(const Json& v) {
  return v.is_string() && (v == "inf" || v == "-inf" || v == "nan" || v == "nan:any");
}

double as_double(const Json& v) {
  if (v.is_number()) return v.get<double>();
  const auto s = v.get<std::string>();
  if (s == "inf") return INFINITY;
  if (s == "-inf") return -INFINITY;
  return NAN;
}

std::string show(const Json& v) {
  std::string s = v.dump();
  if (s.size() > 200) s = s.substr(0, 200) + "...";
  return s;
}

}  // namespace

std::string compare(const Json& expected, const Json& actual, const Json& tolerance,
                    const std::string& where) {
  const std::string at = where.empty() ? "" : " at " + where;
  if (expected == "nan:any") {
    return (actual.is_string() && actual.get<std::string>().starts_with("nan"))
               ? ""
               : "expected nan, got " + show(actual) + at;
  }
  if (expected.is_number() || is_special_string(expected)) {
    if (!(actual.is_number() || is_special_string(actual)))
      return "expected number " + show(expected) + ", got " + show(actual) + at;
    if (expected.is_number_integer() && actual.is_number_integer())
      return expected.get<long long>() == actual.get<long long>()
                 ? ""
                 : "expected " + show(expected) + ", got " + show(actual) + at;
    const double e = as_double(expected);
    const double a = as_double(actual);
    if (std::isnan(e) || std::isinf(e) || std::isnan(a) || std::isinf(a)) {
      const bool same = (std::isnan(e) && std::isnan(a)) || e == a;
      return same ? "" : "expected " + show(expected) + ", got " + show(actual) + at;
    }
    const double abs_tol = tolerance.value("abs", 0.0);
    const double rel_tol = tolerance.value("rel", 0.0);
    const double allowed = std::max(abs_tol, rel_tol * std::fabs(e));
    if (std::fabs(a - e) <= allowed) return "";
    std::ostringstream os;
    os.precision(17);
    os << "expected " << e << ", got " << a << " (|diff| " << std::fabs(a - e) << " > " << allowed
       << ")" << at;
    return os.str();
  }
  if (expected.is_array()) {
    if (!actual.is_array()) return "expected an array, got " + show(actual) + at;
    if (expected.size() != actual.size())
      return "expected " + std::to_string(expected.size()) + " elements, got " +
             std::to_string(actual.size()) + at;
    for (std::size_t i = 0; i < expected.size(); ++i) {
      std::string d = compare(expected[i], actual[i], tolerance, where + "[" + std::to_string(i) + "]");
      if (!d.empty()) return d;
    }
    return "";
  }
  if (expected.is_object()) {
    if (!actual.is_object()) return "expected an object, got " + show(actual) + at;
    for (const auto& [k, v] : expected.items()) {
      if (!actual.contains(k)) return "missing output '" + k + "'" + at;
      std::string d = compare(v, actual.at(k), tolerance, where.empty() ? k : where + "." + k);
      if (!d.empty()) return d;
    }
    return "";
  }
  return expected == actual ? "" : "expected " + show(expected) + ", got " + show(actual) + at;
}

namespace {
const Json& tolerance_of(const Json& group, const Json& test) {
  if (test.contains("tolerance")) return test.at("tolerance");
  return group.at("tolerance");
}
}  // namespace

std::string judge(const Json& group, const Json& test, const Json& actual) {
  const Json& expected = test.at("expected");
  const std::string result = test.at("result").get<std::string>();
  if (result == "invalid") {
    if (!actual.contains("error"))
      return "expected error " + expected.value("error", std::string("?")) + ", got " + actual.dump();
    if (actual.at("error") != expected.at("error"))
      return "expected error " + expected.at("error").dump() + ", got " + actual.at("error").dump() + ": " +
             actual.value("message", std::string());
    return "";
  }
  if (actual.contains("error")) {
    const Json& kind = actual.at("error");
    return "unexpected " + (kind.is_string() ? kind.get<std::string>() : kind.dump()) + ": " +
           actual.value("message", std::string());
  }
  return compare(expected, actual, tolerance_of(group, test));
}

namespace {


/// Runs one test. Returns the actual output, or {"error": kind} when the rule threw.
Json run_rule(const rules::Rule& rule, const Json& input) {
  try {
    return rule.eval(input);
  } catch (const UsageError&) {
    throw;  // a malformed vector is the vector's fault, not a result
  } catch (const Error& e) {
    return Json{{"error", e.kind()}, {"message", e.what()}};
  }
}

CaseResult check_test(const Json& doc, const Json& group, const Json& test, const rules::Rule& rule,
                      const std::string& file) {
  CaseResult r;
  r.file = file;
  r.rule = rule.id;
  r.tc_id = test.at("tcId").get<long long>();
  try {
    if (test.at("expected").is_null()) {
      r.status = Status::fail;
      r.message = "expected is null: run `pathref golden regenerate`";
      return r;
    }
    // A test whose input needs no merging (no group params, no interpretation) is run on its
    // own input object, not on a copy of it (a grid vector's input holds the whole map).
    const bool direct = !group.contains("params") && !test.contains("interpretation") &&
                        test.contains("input") && test.at("input").is_object();
    r.message = judge(group, test, direct ? run_rule(rule, test.at("input"))
                                          : run_rule(rule, compose_input(doc, group, test)));
    if (!r.message.empty()) r.status = Status::fail;
  } catch (const std::exception& e) {
    r.status = Status::fail;
    r.message = std::string("malformed vector: ") + e.what();
  }
  return r;
}

}  // namespace

Report check_document(const Json& doc, const std::string& file) {
  Report report;
  const std::string id = doc.at("rule").get<std::string>();
  const rules::Rule* rule = rules::registry().find(id);
  if (rule == nullptr) {
    report.cases.push_back(CaseResult{file, id, 0, Status::fail, "rule not implemented: " + id});
    return report;
  }
  for (const Json& group : doc.at("testGroups"))
    for (const Json& test : group.at("tests"))
      report.cases.push_back(check_test(doc, group, test, *rule, file));
  return report;
}

std::vector<fs::path> golden_files(const fs::path& dir) {
  if (!fs::is_directory(dir))
    throw UsageError("not a directory: '" + dir.string() + "' (give the golden folder, e.g. pathref golden check golden/)");
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file() || entry.path().extension() != ".json") continue;
    if (entry.path().parent_path().filename() == "schema") continue;
    files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  if (files.empty())
    throw UsageError("no golden vectors in '" + dir.string() + "' (no *.json file outside schema/)");
  return files;
}

namespace {
/// `obj[key]` of the JSON type `type`, or a UsageError naming the file, where and the key.
const Json& need(const Json& obj, const char* key, Json::value_t type, const std::string& file,
                 const std::string& where) {
  const auto it = obj.is_object() ? obj.find(key) : obj.end();
  const char* tname = type == Json::value_t::string ? "a string" : type == Json::value_t::array ? "an array" : "an object";
  if (!obj.is_object() || it == obj.end())
    throw UsageError(file + ": malformed golden file: " + where + " has no '" + key + "' (" + tname +
                     "; spec/golden-format.md)");
  if (it->type() != type)
    throw UsageError(file + ": malformed golden file: " + where + "'" + key + "' must be " + tname);
  return *it;
}
}  // namespace

Json read_document(const fs::path& p) {
  const std::string file = p.string();
  const Json doc = io::parse_json_text(io::read_text_file(file, "golden file"), file);
  (void)need(doc, "rule", Json::value_t::string, file, "the document");
  std::size_t g = 0;
  for (const Json& group : need(doc, "testGroups", Json::value_t::array, file, "the document")) {
    ++g;
    const std::string where = "testGroups[" + std::to_string(g - 1) + "]";
    (void)need(group, "tolerance", Json::value_t::object, file, where);
    std::size_t t = 0;
    for (const Json& test : need(group, "tests", Json::value_t::array, file, where)) {
      const std::string w = where + ".tests[" + std::to_string(t++) + "]";
      if (!test.is_object() || !test.contains("tcId") || !test.at("tcId").is_number_integer())
        throw UsageError(file + ": malformed golden file: " + w + " has no integer 'tcId'");
      (void)need(test, "result", Json::value_t::string, file, w);
      if (!test.contains("expected"))
        throw UsageError(file + ": malformed golden file: " + w + " (tcId " + test.at("tcId").dump() +
                         ") has no 'expected'");
    }
  }
  return doc;
}

Report check_directory(const fs::path& dir) {
  Report report;
  for (const auto& p : golden_files(dir)) {
    Report r = check_document(read_document(p), p.string());
    report.cases.insert(report.cases.end(), r.cases.begin(), r.cases.end());
  }
  return report;
}

Json regenerate_document(const Json& doc, const std::string& file) {
  Json out = doc;
  const std::string id = doc.at("rule").get<std::string>();
  const rules::Rule* rule = rules::registry().find(id);
  if (rule == nullptr) throw UsageError(file + ": rule not implemented: " + id);
  std::size_t n = 0;
  for (Json& group : out.at("testGroups")) {
    const std::string provenance = group.at("provenance").get<std::string>();
    // Only characterization values come from the library; every other provenance is a value
    // from outside it (a person, a paper, an independent oracle) and is verified, never written.
    const bool verify_only = provenance != "characterization";
    for (Json& test : group.at("tests")) {
      ++n;
      Json actual = run_rule(*rule, compose_input(out, group, test));
      actual.erase("message");
      Json& expected = test["expected"];
      const std::string result = test.at("result").get<std::string>();
      Json fresh;
      if (result == "invalid") {
        if (!actual.contains("error"))
          throw UsageError(file + " tcId " + test.at("tcId").dump() +
                           ": marked invalid but the rule returned " + actual.dump());
        fresh = Json{{"error", actual.at("error")}};
      } else {
        if (actual.contains("error"))
          throw UsageError(file + " tcId " + test.at("tcId").dump() + ": rule threw " +
                           actual.at("error").get<std::string>());
        if (expected.is_object()) {
          fresh = Json::object();
          for (const auto& [k, v] : expected.items()) {
            if (!actual.contains(k))
              throw UsageError(file + " tcId " + test.at("tcId").dump() + ": no output " + k);
            fresh[k] = actual.at(k);
          }
        } else {
          fresh = actual;
        }
      }
      if (expected.is_null()) {
        if (verify_only)
          throw UsageError(file + " tcId " + test.at("tcId").dump() + ": " + provenance +
                           "-provenance values must be written by hand, not generated");
        expected = fresh;
      } else if (verify_only) {
        const std::string d = compare(expected, fresh, tolerance_of(group, test));
        if (!d.empty())
          throw DomainError(file + " tcId " + test.at("tcId").dump() + " (" + provenance +
                            " provenance, not rewritten): " + d);
      } else {
        expected = fresh;
      }
    }
  }
  out["numberOfTests"] = n;
  return out;
}

namespace {

/// A finite double exactly as Python's repr() writes it (the shortest digits that round-trip,
/// nearest to the value; exponent form when the decimal exponent is < -4 or >= 16, else plain
/// with at least one fractional digit). nlohmann's dump() differs: its Grisu2 digits are not
/// always the shortest, and it switches to exponent form from 1e15 on.
std::string python_float_repr(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::scientific);
  const std::string sci(buf, r.ptr);  // [-]d[.ddd]e[+-]XX, shortest round-trip digits
  const std::size_t epos = sci.find('e');
  std::string mant = sci.substr(0, epos);
  const int exp10 = std::stoi(sci.substr(epos + 1));
  std::string sign;
  if (!mant.empty() && mant[0] == '-') {
    sign = "-";
    mant.erase(0, 1);
  }
  std::string digits;
  for (const char c : mant)
    if (c != '.') digits.push_back(c);
  const int ndigits = static_cast<int>(digits.size());
  const int decpt = exp10 + 1;  // position of the decimal point after the first digit
  if (decpt <= -4 || decpt > 16) {
    std::string out = sign + digits.substr(0, 1);
    if (ndigits > 1) out += "." + digits.substr(1);
    const int a = exp10 < 0 ? -exp10 : exp10;
    out += exp10 < 0 ? "e-" : "e+";
    if (a < 10) out += "0";
    return out + std::to_string(a);
  }
  if (decpt <= 0) return sign + "0." + std::string(static_cast<std::size_t>(-decpt), '0') + digits;
  if (decpt < ndigits)
    return sign + digits.substr(0, static_cast<std::size_t>(decpt)) + "." +
           digits.substr(static_cast<std::size_t>(decpt));
  return sign + digits + std::string(static_cast<std::size_t>(decpt - ndigits), '0') + ".0";
}

void write_canonical(const Json& v, int depth, std::string& out) {
  const std::string indent(static_cast<std::size_t>(2 * (depth + 1)), ' ');
  const std::string close(static_cast<std::size_t>(2 * depth), ' ');
  if (v.is_object()) {
    if (v.empty()) {
      out += "{}";
      return;
    }
    out += "{\n";
    bool first = true;
    for (const auto& [k, x] : v.items()) {  // std::map: keys in byte (= code point) order
      if (!first) out += ",\n";
      first = false;
      out += indent + Json(k).dump() + ": ";
      write_canonical(x, depth + 1, out);
    }
    out += "\n" + close + "}";
  } else if (v.is_array()) {
    if (v.empty()) {
      out += "[]";
      return;
    }
    out += "[\n";
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (i > 0) out += ",\n";
      out += indent;
      write_canonical(v[i], depth + 1, out);
    }
    out += "\n" + close + "]";
  } else if (v.is_number_float()) {
    const double d = v.get<double>();
    if (!std::isfinite(d))
      throw UsageError("non-finite number in a golden document: write \"inf\", \"-inf\" or \"nan\"");
    out += python_float_repr(d);
  } else {
    out += v.dump();  // integers, strings (UTF-8 kept, control characters escaped), bools, null
  }
}

}  // namespace

std::string canonical_text(const Json& doc) {
  std::string out;
  write_canonical(doc, 0, out);
  return out + "\n";
}

}  // namespace pathref::golden
