#include "pathref/golden/runner.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "pathref/core/error.hpp"
#include "pathref/io/json_reader.hpp"
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

/// A value in a message: its compact JSON, at most 200 bytes, control bytes escaped.
std::string show(const Json& v) {
  return io::printable(v.dump(-1, ' ', false, Json::error_handler_t::replace), 200);
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
  // What the implementation said, bounded: an answer may come from another program (conform).
  const auto said = [&actual] {
    const auto it = actual.find("message");
    return it != actual.end() && it->is_string() ? io::printable(it->get_ref<const std::string&>(), 300) : std::string();
  };
  if (result == "invalid") {
    if (!actual.contains("error"))
      return "expected error " + show(expected.value("error", Json("?"))) + ", got " + show(actual);
    if (actual.at("error") != expected.at("error"))
      return "expected error " + show(expected.at("error")) + ", got " + show(actual.at("error")) + ": " + said();
    return "";
  }
  if (actual.contains("error")) {
    const Json& kind = actual.at("error");
    return "unexpected " + (kind.is_string() ? io::printable(kind.get_ref<const std::string&>(), 80) : show(kind)) +
           ": " + said();
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

Json read_document(const fs::path& p) {
  const std::string file = p.string();
  const std::string text = io::read_text_file(file, "golden file");
  const Json doc = io::parse_json_text(text, file);
  check_document_shape(doc, file, text);
  return doc;
}

void check_document_shape(const Json& doc, const std::string& file, std::string_view text) {
  // The constraints of golden/schema/golden_v1.schema.json that the runner relies on, checked
  // before any vector runs (tools/golden-lint checks the whole schema): ParseError at the value.
  const io::JsonReader rd(file, text);
  const auto need = [&rd](const Json& obj, const std::string& ptr, const char* key, const char* what) -> const Json& {
    return rd.need(obj, ptr, key, what);
  };
  if (!doc.is_object()) rd.fail("", "expected a golden_v1 document (a JSON object), got " + rd.kind(doc));
  (void)rd.string(need(doc, "", "rule", "the rule id, a string"), "/rule");
  const Json& groups = need(doc, "", "testGroups", "an array of at least one test group");
  if (!groups.is_array() || groups.empty())
    rd.fail("/testGroups", "expected an array of at least one test group, got " +
                               (groups.is_array() ? std::string("an empty array") : rd.kind(groups)));
  std::size_t count = 0;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const std::string gp = "/testGroups/" + std::to_string(g);
    const Json& group = groups[g];
    if (!group.is_object()) rd.fail(gp, "expected a test group (an object), got " + rd.kind(group));
    const Json& tol = need(group, gp, "tolerance", "an object {abs, rel, why}");
    if (!tol.is_object()) rd.fail(gp + "/tolerance", "expected an object {abs, rel, why}, got " + rd.kind(tol));
    (void)rd.string(need(group, gp, "provenance", "where the expected values come from, a string"), gp + "/provenance");
    if (const Json* params = io::find(group, "params"); params != nullptr && !params->is_object())
      rd.fail(gp + "/params", "expected an object of inputs, got " + rd.kind(*params));
    for (const char* k : {"abs", "rel"}) {
      const Json& v = need(tol, gp + "/tolerance", k, "a number >= 0");
      (void)rd.number(v, gp + "/tolerance/" + k, 0.0, 1e308);
    }
    if (const Json* u = io::find(tol, "ulps")) (void)rd.integer(*u, gp + "/tolerance/ulps", 0, std::int64_t{1} << 53);
    const Json& tests = need(group, gp, "tests", "an array of at least one test");
    if (!tests.is_array() || tests.empty())
      rd.fail(gp + "/tests", "expected an array of at least one test, got " +
                                 (tests.is_array() ? std::string("an empty array") : rd.kind(tests)));
    for (std::size_t t = 0; t < tests.size(); ++t) {
      const std::string tp = gp + "/tests/" + std::to_string(t);
      const Json& test = tests[t];
      if (!test.is_object()) rd.fail(tp, "expected a test (an object), got " + rd.kind(test));
      (void)rd.integer(need(test, tp, "tcId", "an integer >= 1"), tp + "/tcId", 1, std::int64_t{1} << 53);
      const std::string result = rd.string(need(test, tp, "result", "valid, invalid or acceptable"), tp + "/result");
      if (result != "valid" && result != "invalid" && result != "acceptable")
        rd.fail(tp + "/result", "expected \"valid\", \"invalid\" or \"acceptable\", got \"" + io::printable(result) + "\"");
      const Json& expected = need(test, tp, "expected", "the expected output (null until generated)");
      if (result == "invalid" && !expected.is_null()) {
        if (!expected.is_object()) rd.fail(tp + "/expected", "expected {\"error\": KIND} for an invalid test, got " + rd.kind(expected));
        (void)rd.string(need(expected, tp + "/expected", "error", "the error kind, a string"), tp + "/expected/error");
      }
      if (const Json* in = io::find(test, "input"); in != nullptr && !in->is_object())
        rd.fail(tp + "/input", "expected an object of inputs, got " + rd.kind(*in));
      if (const Json* interp = io::find(test, "interpretation")) {
        if (!interp->is_object()) rd.fail(tp + "/interpretation", "expected an object {NOTE: OPTION}, got " + rd.kind(*interp));
        const Json* notes = io::find(doc, "notes");
        for (auto it = interp->begin(); it != interp->end(); ++it) {
          const std::string ip = io::JsonReader::child(tp + "/interpretation", it.key());
          const Json* note = notes != nullptr ? io::find(*notes, it.key().c_str()) : nullptr;
          const Json* param = note != nullptr ? io::find(*note, "param") : nullptr;
          if (param == nullptr || !param->is_string())
            rd.fail(ip, "expected the name of a note of /notes that has a \"param\" (an INTERPRETATION note)");
        }
      }
      if (const Json* tt = io::find(test, "tolerance")) {
        if (!tt->is_object()) rd.fail(tp + "/tolerance", "expected an object {abs, rel, why}, got " + rd.kind(*tt));
        for (const char* k : {"abs", "rel"})
          (void)rd.number(need(*tt, tp + "/tolerance", k, "a number >= 0"), tp + "/tolerance/" + k, 0.0, 1e308);
      }
      ++count;
    }
  }
  if (const Json* n = io::find(doc, "numberOfTests")) {
    const auto declared = rd.integer(*n, "/numberOfTests", 1, std::int64_t{1} << 53);
    if (static_cast<std::size_t>(declared) != count)
      rd.fail("/numberOfTests", "expected " + std::to_string(count) + " (the number of tests in all groups), got " +
                                    std::to_string(declared));
  }
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
