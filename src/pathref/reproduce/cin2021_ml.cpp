#include "pathref/io/wall_following.hpp"
#include "pathref/reproduce/cin2021_ml.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <span>
#include <stdexcept>

#include "pathref/core/error.hpp"
#include "pathref/io/svg.hpp"
#include "pathref/ml/classifier.hpp"
#include "pathref/ml/folds.hpp"
#include "pathref/reproduce/runs.hpp"
#include "pathref/reproduce/stats.hpp"

namespace pathref::reproduce {
namespace {

/// The reconstructed rules (spec/index) a claim "CLASSIFIER-PROTOCOL[@reading]" rests on
/// (attach_rules; reproduce.markdown): the data, the split (cin2021.folds), accuracy (Eq. 7) and
/// the classifier's own rules.
std::vector<std::string> cin2021_ml_claim_rules(const std::string& id) {
  std::vector<std::string> r{"cin2021.data", "cin2021.folds", "cin2021.eq7"};
  const std::string c = id.substr(0, id.find('-'));
  if (c == "rf") r.insert(r.end(), {"cin2021.gini", "cin2021.eq6"});
  else if (c == "knn") r.insert(r.end(), {"cin2021.eq4", "cin2021.knn"});
  else if (c == "svm") r.insert(r.end(), {"cin2021.eq2", "cin2021.eq3"});
  else if (c == "gnb" || c == "mnb") r.emplace_back("cin2021.eq1");
  else throw std::logic_error("cin2021_ml_claim_rules: unknown classifier in claim id '" + id + "'");
  return r;
}

using namespace pathref::ml;

struct Variant {
  const char* name;
  const char* label;
  Kind kind;
  const char* set;  // name=value applied to the defaults, "" for none
  const char* paper_name;  // the paper's classifier this row answers
};

// The paper's classifiers (pathref's defaults) and the scikit-learn < 0.22 defaults the paper's
// numbers suggest (SVC gamma='auto', RandomForest n_estimators=10).
const Variant variants[] = {
    {"rf", "RF (100 trees, Eq. 6 majority)", Kind::rf, "", "RF"},
    {"rf-10", "RF (10 trees: scikit-learn < 0.22 default)", Kind::rf, "trees=10", "RF"},
    {"knn", "KNN (k = 5)", Kind::knn, "", "KNN"},
    {"svm", "SVM (RBF, C = 1, gamma = scale)", Kind::svm, "", "SVM"},
    {"svm-auto", "SVM (gamma = auto = 1/d: scikit-learn < 0.22 default)", Kind::svm, "gamma=auto", "SVM"},
    {"gnb", "GNB (var_smoothing 1e-9)", Kind::gnb, "", "GNB"},
    {"mnb", "MNB (alpha 1)", Kind::mnb, "", "MNB"},
};

struct PaperNumber {
  const char* classifier;
  const char* main_variant;
  const char* holdout;
  const char* tenfold;
};
const PaperNumber paper[] = {{"RF", "rf", "99.9", "99.8"},  {"KNN", "knn", "95.5", "93.2"}, {"SVM", "svm", "93.7", "91.5"},
                             {"GNB", "gnb", "89.7", "88.4"}, {"MNB", "mnb", "58.7", "58.3"}};

Params params_of(const Variant& v, bool quick) {
  Params p;
  if (std::string(v.set).size() > 0) {
    const std::string s = v.set;
    const auto eq = s.find('=');
    p.set(s.substr(0, eq), s.substr(eq + 1));
  }
  if (quick && v.kind == Kind::rf) p.forest.trees = 10;
  return p;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

Json summary_json(const std::vector<double>& v) {
  const Summary s = summarize(v);
  return Json{{"n", v.size()}, {"mean", s.mean ? Json(*s.mean) : Json()}, {"sd", s.std ? Json(*s.std) : Json()},
              {"min", s.min ? Json(*s.min) : Json()}, {"max", s.max ? Json(*s.max) : Json()}, {"values", v}};
}

/// The split evidence (not a verdict): the paper's number inside [min - half a printed unit,
/// max + half a printed unit] of the per-seed accuracies.
bool in_range(const Json& s, double paper_pct, int decimals) {
  if (s.is_null() || s.at("min").is_null()) return false;
  const double half = 0.5 * std::pow(10.0, -decimals);
  return paper_pct >= 100.0 * s.at("min").get<double>() - half && paper_pct <= 100.0 * s.at("max").get<double>() + half;
}

}  // namespace

bool within_last_digit(double value, std::string_view printed) {
  const double printed_value = std::stod(std::string(printed));
  return std::abs(value - printed_value) < std::pow(10.0, -printed_decimals(printed));
}

Claim tenfold_printed_claim(const std::string& id, const std::string& text, double accuracy_pct,
                            const std::string& printed) {
  Claim c;
  c.id = id;
  c.text = text;
  c.source = "§3.3, Fig. 4";
  c.paper = printed + " %";
  const int dec = printed_decimals(printed);
  const double diff = accuracy_pct - std::stod(printed);
  c.ours = fmt::format("{} (prints as {}; {}{} pp)", fixed(accuracy_pct, 3), fixed(accuracy_pct, dec),
                       diff >= 0 ? "+" : "−", fixed(std::abs(diff), 3));
  c.rule = "printed digits (reproduce.judge, stated before the runs): pathref's 10-fold accuracy, a deterministic "
           "computation on the paper's folds, rounded to the paper's decimals equals the printed number";
  const Judgement j = judge_printed(accuracy_pct, printed, Sense::higher_is_better);
  c.verdict = j.verdict;
  c.direction = j.direction;
  c.statistics = Json{{"n", Json{{"kind", "printed"}, {"value", accuracy_pct}, {"paper", printed},
                                 {"printed_as", fixed(accuracy_pct, dec)}, {"difference_pp", diff},
                                 {"judgement", judgement_json(j)},
                                 {"post_hoc_within_last_digit", within_last_digit(accuracy_pct, printed)}}},
                      {"2n", nullptr}};
  c.note = fmt::format("post-hoc alternative, not deciding (chosen after seeing MNB's 58.376, disclosed): within one unit "
                       "of the last printed digit (|diff| < {} pp): {}",
                       fixed(std::pow(10.0, -dec), dec), within_last_digit(accuracy_pct, printed) ? "yes" : "no");
  return c;
}

Json run_cin2021_ml(const Cin2021MlConfig& cfg) {
  const auto t_all = std::chrono::steady_clock::now();
  require(cfg.seeds >= 2, "cin2021-ml: seeds must be >= 2 (an interval over seeds needs 2)");
  const Dataset d = io::read_wall_following(cfg.data_file);
  require(d.features == 4, "cin2021-ml: the paper's protocol uses the 4-sensor file (sensor_readings_4.data)");
  const auto say = [&](const std::string& s) { if (cfg.progress) cfg.progress(s); };
  const int n = cfg.seeds;
  const int n2 = 2 * cfg.seeds;  // reproduce.judge: verdicts at n and at 2n seeds
  const BootstrapOptions bo{cfg.first_seed, 2000, 0.95};
  Json results = Json::object();
  // tenfold: deterministic classifiers once; the forests once per forest seed (S .. S + 2n - 1)
  const std::vector<int> folds = stratified_kfold(d.y, 10);
  for (const Variant& v : variants) {
    const auto t0 = std::chrono::steady_clock::now();
    const Params p = params_of(v, cfg.quick);
    results[v.name]["label"] = v.label;
    results[v.name]["params"] = p.to_json(v.kind);
    if (v.kind == Kind::rf) {
      std::vector<Scores> per_seed(static_cast<std::size_t>(n2));
      parallel_for(per_seed.size(), [&](std::size_t i) {
        Params q = p;
        q.seed = cfg.first_seed + static_cast<std::uint32_t>(i);
        per_seed[i] = score(d.y, cross_val_predict(v.kind, d, folds, q), d.classes);
      });
      std::vector<double> acc, f1, mcc;
      for (const Scores& s : per_seed) {
        acc.push_back(s.accuracy);
        f1.push_back(s.f1_macro);
        mcc.push_back(s.mcc);
      }
      results[v.name]["params"]["seed"] = fmt::format("{}..{} (one tenfold run per forest seed)", cfg.first_seed,
                                                      cfg.first_seed + static_cast<std::uint32_t>(n2) - 1);
      results[v.name]["tenfold"] = Json{{"forest_seeds", Json::array({cfg.first_seed, cfg.first_seed + static_cast<std::uint32_t>(n2) - 1})},
                                        {"accuracy_per_seed", acc},
                                        {"accuracy", summary_json(acc)},
                                        {"accuracy_ci_n", interval_json(bootstrap_ci(std::span<const double>(acc).first(static_cast<std::size_t>(n)), BootStatistic::mean, bo))},
                                        {"accuracy_ci_2n", interval_json(bootstrap_ci(acc, BootStatistic::mean, bo))},
                                        {"f1_macro", mean(f1)}, {"mcc", mean(mcc)},
                                        {"wall_s", seconds_since(t0)}};
      say(fmt::format("tenfold {}: mean accuracy {:.3f} % over {} forest seeds ({:.1f} s)", v.name, 100 * mean(acc), n2,
                      seconds_since(t0)));
      continue;
    }
    const std::vector<int> pred = cross_val_predict(v.kind, d, folds, p);
    const Scores s = score(d.y, pred, d.classes);
    results[v.name]["tenfold"] = Json{{"accuracy", s.accuracy}, {"f1_macro", s.f1_macro}, {"mcc", s.mcc},
                                      {"precision_macro", s.precision_macro}, {"recall_macro", s.recall_macro},
                                      {"wall_s", seconds_since(t0)}};
    say(fmt::format("tenfold {}: accuracy {:.3f} % ({:.1f} s)", v.name, 100 * s.accuracy, seconds_since(t0)));
  }
  // hold-out under both readings, 2n split seeds
  const std::pair<const char*, double> readings[] = {{"stated", 0.7}, {"swapped", 0.3}};
  Json split_sizes = Json::object();
  for (const auto& [reading, frac] : readings) {
    std::vector<std::vector<double>> acc(std::size(variants));
    for (int r = 0; r < n2; ++r) {
      const std::uint32_t seed = cfg.first_seed + static_cast<std::uint32_t>(r);
      rng::Stream s(seed);
      const std::vector<bool> test = holdout_split(d.rows(), frac, s);
      const auto train_rows = rows_where(test, false);
      const auto test_rows = rows_where(test, true);
      split_sizes[reading] = Json{{"test_fraction", frac}, {"train", train_rows.size()}, {"test", test_rows.size()}};
      const Dataset tr = subset(d, train_rows);
      for (std::size_t k = 0; k < std::size(variants); ++k) {
        const Model m = train(variants[k].kind, tr, params_of(variants[k], cfg.quick));
        std::size_t ok = 0;
        for (const std::size_t i : test_rows)
          if (predict(m, d.row(i)) == d.y[i]) ++ok;
        acc[k].push_back(static_cast<double>(ok) / static_cast<double>(test_rows.size()));
      }
    }
    for (std::size_t k = 0; k < std::size(variants); ++k) {
      Json s = summary_json(std::vector<double>(acc[k].begin(), acc[k].begin() + n));
      s["values_2n"] = acc[k];
      s["summary_2n"] = summary_json(acc[k]);
      s["summary_2n"].erase("values");
      results[variants[k].name]["holdout"][reading] = s;
    }
    say(fmt::format("hold-out {} ({} seeds) done", reading, n2));
  }

  // the split evidence (not a verdict): on the protocol's n seeds
  Json evidence = Json::object();
  for (const auto& [reading, frac] : readings) {
    double z2 = 0.0;
    int inside = 0;
    for (const PaperNumber& pn : paper) {
      const Json& s = results[pn.main_variant]["holdout"][reading];
      const double paper_pct = std::stod(pn.holdout);
      const double m = 100.0 * s.at("mean").get<double>();
      const double sd = s.at("sd").is_null() ? 0.0 : 100.0 * s.at("sd").get<double>();
      const double z = (paper_pct - m) / std::max(sd, 0.05);
      z2 += z * z;
      if (in_range(s, paper_pct, 1)) ++inside;
    }
    evidence[reading] = Json{{"sum_z2", z2}, {"numbers_inside_range", inside},
                             {"z_rule", "z = (paper - mean) / max(sd, 0.05 pp) over the five classifiers' default variants"},
                             {"range_rule", "the paper's number inside [min - 0.05, max + 0.05] of the n per-seed accuracies"}};
  }

  // claims: each of the ten numbers (reproduce.cin2021-ml.judge)
  std::vector<Claim> claims, alternatives;
  const auto pct_values = [&](const Json& s, bool all) {
    std::vector<double> v;
    for (const Json& x : all ? s.at("values_2n") : s.at("values")) v.push_back(100.0 * x.get<double>());
    return v;
  };
  const auto holdout_claim = [&](const std::string& id, const std::string& text, const std::string& variant,
                                 const char* reading, const std::string& printed) {
    Claim c;
    c.id = id;
    c.text = text;
    c.source = "§3.3, Fig. 3";
    c.paper = printed + " %";
    const Json& s = results[variant]["holdout"][reading];
    const auto vn = pct_values(s, false), v2 = pct_values(s, true);
    value_claim(c, vn, v2, std::stod(printed), Quantity::percent, Sense::higher_is_better, BootStatistic::mean, bo, 2);
    c.rule = fmt::format("95 % bootstrap interval of the mean accuracy over the {} split seeds within {} ± 5 pp "
                         "(percent margin, stats.margin); {} split ({} training rows)",
                         n, printed, reading, split_sizes[reading].at("train").get<std::size_t>());
    return c;
  };
  const auto rf_tenfold_claim = [&](const std::string& id, const std::string& text, const std::string& variant,
                                    const std::string& printed) {
    Claim c;
    c.id = id;
    c.text = text;
    c.source = "§3.3, Fig. 4";
    c.paper = printed + " %";
    std::vector<double> v2;
    for (const Json& x : results[variant]["tenfold"]["accuracy_per_seed"]) v2.push_back(100.0 * x.get<double>());
    const std::vector<double> vn(v2.begin(), v2.begin() + n);
    value_claim(c, vn, v2, std::stod(printed), Quantity::percent, Sense::higher_is_better, BootStatistic::mean, bo, 3);
    c.rule = fmt::format("the forest is random: 95 % bootstrap interval of the mean tenfold accuracy over {} forest "
                         "seeds within {} ± 5 pp (percent margin, stats.margin)", n, printed);
    c.note = fmt::format("the mean prints as {} (printed digits shown, not deciding for a random quantity)",
                         fixed(mean(vn), printed_decimals(printed)));
    return c;
  };
  for (const PaperNumber& pn : paper) {
    const std::string v = pn.main_variant;
    const std::string cls = pn.classifier;
    // hold-out: the swapped split (70 % training) is the reading the evidence favours; the stated one beside it
    {
      const std::string id = v + "-holdout";
      const std::string text = fmt::format("{} hold-out (Fig. 3) \"comprehensive evaluation index\" (read as accuracy) {} %",
                                           cls, pn.holdout);
      Claim c = holdout_claim(id, text, v, "swapped", pn.holdout);
      Claim st = holdout_claim(id + "@stated", text + ", stated split (30 % training)", v, "stated", pn.holdout);
      st.depends_on.push_back("the stated split 1636 / 3820 (the alternative of " + id + ")");
      c.depends_on.push_back("the swapped split, 70 % training (the evidence below; alternative: " + st.id + ")");
      alternatives.push_back(st);
      if (v == "svm" || v == "rf") {
        const std::string alt_v = v == "svm" ? "svm-auto" : "rf-10";
        const std::string what = v == "svm" ? "gamma = auto" : "10 trees";
        Claim a = holdout_claim(id + "@" + alt_v, text + ", " + what + " (scikit-learn < 0.22's default)", alt_v, "swapped",
                                pn.holdout);
        a.depends_on.push_back(what + ", scikit-learn < 0.22's default (the alternative of " + id + ")");
        c.depends_on.push_back(std::string(v == "svm" ? "gamma = scale" : "100 trees") +
                               ", today's scikit-learn default (alternative: " + a.id + ")");
        alternatives.push_back(a);
      }
      claims.push_back(c);
    }
    // tenfold
    {
      const std::string id = v + "-tenfold";
      const std::string text = fmt::format(
          "{} tenfold cross-validation (Fig. 4) \"comprehensive evaluation index\" (read as accuracy) {} %", cls, pn.tenfold);
      Claim c = v == "rf" ? rf_tenfold_claim(id, text, v, pn.tenfold)
                          : tenfold_printed_claim(id, text, 100.0 * results[v]["tenfold"]["accuracy"].get<double>(), pn.tenfold);
      if (v == "svm" || v == "rf") {
        const std::string alt_v = v == "svm" ? "svm-auto" : "rf-10";
        const std::string what = v == "svm" ? "gamma = auto" : "10 trees";
        const std::string atext = text + ", " + what + " (scikit-learn < 0.22's default)";
        Claim a = v == "rf" ? rf_tenfold_claim(id + "@" + alt_v, atext, alt_v, pn.tenfold)
                            : tenfold_printed_claim(id + "@" + alt_v, atext,
                                                    100.0 * results[alt_v]["tenfold"]["accuracy"].get<double>(), pn.tenfold);
        a.depends_on.push_back(what + ", scikit-learn < 0.22's default (the alternative of " + id + ")");
        c.depends_on.push_back(std::string(v == "svm" ? "gamma = scale" : "100 trees") +
                               ", today's scikit-learn default (alternative: " + a.id + ")");
        alternatives.push_back(a);
      }
      claims.push_back(c);
    }
  }
  const auto to_json = [](const std::vector<Claim>& v) {
    Json a = Json::array();
    for (const Claim& c : v) a.push_back(claim_json(c));
    return a;
  };
  Json doc{{"paper", "cin2021"},
           {"section", "§3.3, Figs. 3-4"},
           {"data", {{"file", cfg.data_file}, {"rows", d.rows()}, {"features", d.features}}},
           {"protocol",
            {{"tenfold", "stratified 10-fold without shuffling (identical to scikit-learn StratifiedKFold(10)); the "
                         "forests once per forest seed"},
             {"holdout", {{"seeds", n}, {"seeds_2n", n2}, {"first_seed", cfg.first_seed}, {"splits", split_sizes},
                          {"rule", "spec r[cin2021.folds]: n_test = ceil(f n), Fisher-Yates from rng::Stream(seed)"}}},
             {"forest_seeds", Json::array({cfg.first_seed, cfg.first_seed + static_cast<std::uint32_t>(n2) - 1})},
             {"bootstrap", {{"resamples", bo.resamples}, {"level", bo.level}, {"seed", bo.seed}}},
             {"judge", "reproduce.cin2021-ml.judge"},
             {"quick", cfg.quick}}},
           {"results", results},
           {"evidence", evidence},
           {"claims", to_json(claims)},
           {"reading_claims", to_json(alternatives)},
           {"sklearn", cfg.sklearn},
           {"provenance", provenance_json(cfg.provenance)}};
  attach_rules_all(doc["claims"], cin2021_ml_claim_rules);
  attach_rules_all(doc["reading_claims"], cin2021_ml_claim_rules);
  doc["provenance"]["total_wall_s"] = seconds_since(t_all);
  return doc;
}

namespace {

std::string pct(const Json& v, int decimals = 2) {
  if (v.is_null()) return "—";
  return fixed(100.0 * v.get<double>(), decimals);
}

std::string mean_sd(const Json& s) {
  if (s.is_null() || s.at("mean").is_null()) return "—";
  return fmt::format("{} ± {} [{}, {}]", pct(s.at("mean")), pct(s.at("sd")), pct(s.at("min")), pct(s.at("max")));
}

Json sk_summary(const Json& doc, const char* table, const char* reading, const char* variant) {
  const Json& v = at_or_null(doc, {"sklearn", table, reading, variant});
  if (!v.is_array() || v.empty()) return Json();
  std::vector<double> x = v.get<std::vector<double>>();
  return summary_json(x);
}

}  // namespace

std::string cin2021_ml_markdown(const Json& doc, const std::string& json_name) {
  std::string md;
  const Json& proto = doc.at("protocol");
  const Json& ho = proto.at("holdout");
  const int n = ho.at("seeds").get<int>();
  const int n2 = ho.value("seeds_2n", n);
  const int s0 = ho.at("first_seed").get<int>();
  md += "# Reproduction: cin2021 §3 — the machine-learning obstacle-avoidance decision model\n\n";
  md += "<!-- generated by `pathref reproduce cin2021-ml`; do not edit by hand -->\n\n";
  if (proto.value("quick", false)) md += "**QUICK RUN** (`--quick`: 10-tree forests; a smoke test, not a reproduction).\n\n";
  md += "Wang et al., *Computational Intelligence and Neuroscience* 2021, article 8025730, doi:10.1155/2021/8025730, "
        "§3.3, Figs. 3–4. Data: UCI Wall-Following Robot Navigation, `sensor_readings_4.data` (5,456 rows, the four "
        "simplified distances). Written by `pathref reproduce cin2021-ml`; every number below comes from `" + json_name +
        "`. Rules: spec/cin2021-ml.md (reproduce.cin2021-ml.judge).\n\n";
  md += "The paper reports one \"comprehensive evaluation index\" per classifier and protocol; pathref reads it as "
        "accuracy (rule cin2021.eq7) and reports macro F1 and MCC beside it. scikit-learn's numbers come from "
        "`tools/reproduce/cin2021_ml_sklearn.py` on the same folds and the same hold-out splits";
  const Json& skv = at_or_null(doc, {"sklearn", "sklearn_version"});
  md += skv.is_string() ? fmt::format(" (scikit-learn {}; its file holds the split seeds it was run with).\n\n", skv.get<std::string>())
                        : " (not run: scikit-learn absent).\n\n";
  md += "## How the ten numbers are judged\n\n";
  md += fmt::format(
      "Rules stated before the runs (spec reproduce.cin2021-ml.judge, reproduce.judge, spec/stats.md):\n\n"
      "- **Tenfold, deterministic classifiers (KNN, SVM, GNB, MNB)**: the folds are the paper's (unshuffled "
      "stratified 10-fold, identical to scikit-learn's) and the classifiers deterministic, so pathref computes the "
      "very number the authors computed if their classifier was the same; there is no sampling noise for a margin to "
      "absorb. The rule is the printed-digits rule: pathref's accuracy rounded to the paper's decimals equals the "
      "printed number. Every \"does not hold\" states its direction and its size in percentage points.\n"
      "- **Tenfold RF** (random): one tenfold run per forest seed, seeds {0}–{1} (n = {2}), and again with {3} seeds "
      "({0}–{4}); the 95 % percentile bootstrap interval of the mean accuracy must lie within the paper's number "
      "± 5 pp (the `percent` margin of stats.margin).\n"
      "- **Hold-out** (random splits; the paper's seed is unknown): the same interval rule over the split seeds "
      "{0}–{1}, and again over {0}–{4}. The paper's number is one split; the interval is of pathref's mean.\n"
      "- Verdicts at n and at 2n are both shown; any change is explained. † marks a verdict that rests on a chosen "
      "reading (the split, scikit-learn's version defaults); its alternative is judged in the next section.\n"
      "- **Disclosed post-hoc reading**: an earlier version of this report judged the tenfold numbers by "
      "\"within one unit of the last printed digit\" (|diff| < 0.1 pp), a rule adopted after seeing that MNB's "
      "58.376 % prints as 58.4, not the paper's 58.3. It is shown in its own column below, labelled post hoc, and "
      "decides nothing.\n\n",
      s0, s0 + n - 1, n, n2, s0 + n2 - 1);
  md += "## Verdicts\n\n" + md_verdict_summary(doc.at("claims")) + "\n" + md_claims(doc.at("claims")) + "\n";
  {
    std::string ch;
    for (const Json& c : doc.at("claims"))
      if (c.value("changed", false)) ch += "- " + c.at("id").get<std::string>() + ": " + c.at("change_note").get<std::string>() + "\n";
    md += "### Verdicts that change between n and 2n seeds\n\n" + (ch.empty() ? std::string("None.\n") : ch) + "\n";
  }
  md += "## The same numbers under the alternative readings (†)\n\n"
        "`@stated`: the split as printed (1636 training rows); `@svm-auto`: SVC's `gamma='auto'` (1/d), scikit-learn's "
        "default before 0.22; `@rf-10`: 10 trees, the forest's default before 0.22.\n\n";
  md += md_verdict_summary(doc.at("reading_claims")) + "\n" + md_claims(doc.at("reading_claims")) + "\n";

  md += fmt::format("## Tenfold cross-validation (Fig. 4)\n\nFolds: stratified 10-fold without shuffling, identical to "
                    "scikit-learn's `StratifiedKFold(n_splits=10)` (checked by ctest `cin2021.sklearn`). Accuracy in %. "
                    "The forests: mean [95 % bootstrap CI of the mean] over the n = {} forest seeds (all {} seeds in "
                    "the JSON); scikit-learn's forest is one run (`random_state=0`), its random stream differs.\n\n",
                    n, n2);
  md += md_row({"classifier", "paper", "pathref accuracy", "prints as", "printed-digits rule", "post hoc: within 0.1 pp (not deciding)",
                "scikit-learn accuracy", "pathref macro F1", "pathref MCC", "pathref time (s)"});
  md += "|---|---|---|---|---|---|---|---|---|---|\n";
  const auto paper_of = [](const std::string& v, bool hold) -> std::string {
    if (v == "rf" || v == "rf-10") return hold ? "99.9" : "99.8";
    if (v == "knn") return hold ? "95.5" : "93.2";
    if (v == "svm" || v == "svm-auto") return hold ? "93.7" : "91.5";
    if (v == "gnb") return hold ? "89.7" : "88.4";
    return hold ? "58.7" : "58.3";
  };
  for (const char* v : {"rf", "rf-10", "knn", "svm", "svm-auto", "gnb", "mnb"}) {
    const Json& r = doc.at("results").at(v);
    const Json& t = r.at("tenfold");
    const std::string p = paper_of(v, false);
    std::string acc, printed, rule, post;
    if (t.at("accuracy").is_object()) {
      std::vector<double> vals;
      for (const Json& x : t.at("accuracy_per_seed")) vals.push_back(100.0 * x.get<double>());
      vals.resize(static_cast<std::size_t>(n));
      const double m = mean(vals);
      const Json& ci = t.at("accuracy_ci_n");
      acc = fmt::format("mean {} [{}, {}]", fixed(m, 3), md_number(Json(100.0 * ci[0].get<double>()), 3),
                        md_number(Json(100.0 * ci[1].get<double>()), 3));
      printed = fixed(m, 1);
      rule = "— (random: interval rule)";
      post = "—";
    } else {
      const double a = 100.0 * t.at("accuracy").get<double>();
      acc = fixed(a, 3);
      printed = fixed(a, 1);
      const Judgement j = judge_printed(a, p, Sense::higher_is_better);
      rule = verdict_text(j.verdict, j.direction);
      if (j.verdict != Verdict::holds) rule += fmt::format(" ({}{} pp)", a >= std::stod(p) ? "+" : "−", fixed(std::abs(a - std::stod(p)), 3));
      post = within_last_digit(a, p) ? "yes" : "no";
    }
    md += md_row({r.at("label").get<std::string>(), p, acc, printed, rule, post,
                  pct(at_or_null(doc, {"sklearn", "tenfold", v, "accuracy"}), 3),
                  fixed(t.at("f1_macro").get<double>(), 4), fixed(t.at("mcc").get<double>(), 4),
                  fixed(t.at("wall_s").get<double>(), 1)});
  }
  md += fmt::format("\n## Hold-out (Fig. 3), both readings of the split\n\n"
                    "The paper: \"5456 data, where 1636 are training samples, and 3820 are test samples\". "
                    "**stated**: test fraction 0.7 ({} training / {} test rows); **swapped**: test fraction 0.3 "
                    "({} / {}). The paper's seed is unknown, so each reading is run with n = {} split seeds ({}…{}); "
                    "accuracy in %, mean ± sd [min, max] over the seeds, and the 95 % bootstrap CI of the mean "
                    "(verdicts above; the 2n = {} seeds are in the JSON). scikit-learn runs on the same splits.\n\n",
                    ho.at("splits").at("stated").at("train").get<int>(), ho.at("splits").at("stated").at("test").get<int>(),
                    ho.at("splits").at("swapped").at("train").get<int>(), ho.at("splits").at("swapped").at("test").get<int>(),
                    n, s0, s0 + n - 1, n2);
  const auto ci_of = [&](const Json& s) {
    std::vector<double> v;
    for (const Json& x : s.at("values")) v.push_back(100.0 * x.get<double>());
    if (v.size() < 2) return std::string("—");
    const Interval ci = bootstrap_ci(v, BootStatistic::mean, BootstrapOptions{static_cast<std::uint32_t>(s0), 2000, 0.95});
    return fmt::format("[{}, {}]", fixed(ci.lo, 2), fixed(ci.hi, 2));
  };
  md += md_row({"classifier", "paper", "pathref, stated", "CI, stated", "scikit-learn, stated", "pathref, swapped",
                "CI, swapped", "scikit-learn, swapped"});
  md += "|---|---|---|---|---|---|---|---|\n";
  for (const char* v : {"rf", "rf-10", "knn", "svm", "svm-auto", "gnb", "mnb"}) {
    const Json& r = doc.at("results").at(v);
    md += md_row({r.at("label").get<std::string>(), paper_of(v, true), mean_sd(r.at("holdout").at("stated")),
                  ci_of(r.at("holdout").at("stated")), mean_sd(sk_summary(doc, "holdout", "stated", v)),
                  mean_sd(r.at("holdout").at("swapped")), ci_of(r.at("holdout").at("swapped")),
                  mean_sd(sk_summary(doc, "holdout", "swapped", v))});
  }
  md += "\nscikit-learn with its own `train_test_split(test_size, random_state=seed)` instead of pathref's split "
        "(the same protocol, NumPy's permutation):\n\n";
  md += md_row({"classifier", "stated", "swapped"});
  md += "|---|---|---|\n";
  for (const char* v : {"rf", "knn", "svm", "svm-auto", "gnb", "mnb"})
    md += md_row({v, mean_sd(sk_summary(doc, "holdout_sklearn_split", "stated", v)),
                  mean_sd(sk_summary(doc, "holdout_sklearn_split", "swapped", v))});

  const Json& ev = doc.at("evidence");
  md += "\n## Which split did the authors use?\n\n";
  {
    const double z_sw = ev.at("swapped").at("sum_z2").get<double>(), z_st = ev.at("stated").at("sum_z2").get<double>();
    const int in_sw = ev.at("swapped").at("numbers_inside_range").get<int>();
    const int in_st = ev.at("stated").at("numbers_inside_range").get<int>();
    const char* favoured = z_sw < z_st && in_sw >= in_st ? "swapped** (70 % training)"
                           : z_st < z_sw && in_st >= in_sw ? "stated** (30 % training)"
                                                           : "neither clearly**";
    md += fmt::format(
        "- **The accuracies say: {}. Over the five classifiers' hold-out numbers (n = {} seeds), Σ z² = {} under the "
        "swapped reading against {} under the stated one (z = (paper − mean) / max(sd, 0.05 pp)); {} of the 5 paper "
        "numbers fall inside pathref's per-seed range under the swapped reading, {} under the stated one.",
        favoured, n, fixed(z_sw, 1), fixed(z_st, 1), in_sw, in_st);
    const Json& knn_st = doc.at("results").at("knn").at("holdout").at("stated");
    if (100.0 * knn_st.at("max").get<double>() < 95.5 - 0.05)
      md += fmt::format(" KNN's 95.5 % is above every one of pathref's {} stated-split accuracies (max {} %).", n,
                        pct(knn_st.at("max")));
    md += " (Evidence about the split, not a verdict: with the ± 5 pp margin the verdicts of both readings are in "
          "the tables above.)\n";
  }
  md += "- **The printed counts say: stated, literally.** 1636 / 3820 is exactly what `train_test_split(test_size=0.7)` "
        "(or `train_size=0.3`) gives: ⌈0.7 · 5456⌉ = 3820 test rows. A 70 % training split gives 3819 / 1637, never "
        "1636 / 3820, so the text did not simply swap the two counts of the split that was run.\n";
  md += "- Reading both: the figures were most likely produced with 70 % training (`test_size=0.3`) and the sentence "
        "computed or copied from a `test_size=0.7` call; which one the figures came from cannot be settled from the text. "
        "The headline hold-out verdicts use the swapped reading and mark it (†).\n";
  const auto acc = [&](const char* v) { return fixed(100.0 * doc.at("results").at(v).at("tenfold").at("accuracy").get<double>(), 3); };
  const auto sk = [&](const char* v) { return pct(at_or_null(doc, {"sklearn", "tenfold", v, "accuracy"}), 3); };
  md += fmt::format(
      "- **scikit-learn's version**: the tenfold SVM number 91.5 % is reproduced to the printed digit by "
      "`SVC(gamma='auto')` (γ = 1/d, the default before scikit-learn 0.22: {} %), not by today's `gamma='scale'` "
      "({} %); before 0.22 the random forest's default was 10 trees. KNN 93.2 and GNB 88.4 are reproduced to the "
      "printed digit ({}, {}) by pathref and scikit-learn alike (identical predictions). MNB gives {} % (scikit-learn "
      "{} %), which prints as {}, not the paper's 58.3: the paper's number is truncated rather than rounded, or from "
      "another version or preprocessing — the printed-digits verdict says \"does not hold\" and states by how much.\n\n",
      acc("svm-auto"), acc("svm"), acc("knn"), acc("gnb"), acc("mnb"), sk("mnb"),
      fixed(100.0 * doc.at("results").at("mnb").at("tenfold").at("accuracy").get<double>(), 1));
  md += "## Figures\n\n![hold-out accuracies](cin2021-ml/fig3-holdout.svg)\n\n![tenfold accuracies](cin2021-ml/fig4-tenfold.svg)\n\n";
  md += "## Provenance\n\n" + md_provenance(doc.at("provenance"), json_name);
  return md;
}

std::vector<std::pair<std::string, std::string>> cin2021_ml_figures(const Json& doc) {
  std::vector<std::pair<std::string, std::string>> out;
  const char* order[] = {"rf", "knn", "svm", "gnb", "mnb"};
  const char* names[] = {"RF", "KNN", "SVM", "GNB", "MNB"};
  const double paper_ho[] = {99.9, 95.5, 93.7, 89.7, 58.7};
  const double paper_cv[] = {99.8, 93.2, 91.5, 88.4, 58.3};
  for (int fig = 0; fig < 2; ++fig) {
    const bool ho = fig == 0;
    io::BarChart c{ho ? "Hold-out accuracy, cin2021 Fig. 3: paper vs pathref (swapped split, mean of seeds)"
                      : "Tenfold cross-validation accuracy, cin2021 Fig. 4: paper vs pathref (RF: mean of forest seeds)",
                   "accuracy (%)", {}, {io::Series{"paper", {}, {}}, io::Series{"pathref", {}, {}}}, 100.0, 1};
    for (int k = 0; k < 5; ++k) {
      const Json& r = doc.at("results").at(order[k]);
      const Json& ta = r.at("tenfold").at("accuracy");
      c.groups.emplace_back(names[k]);
      c.bars[0].y.push_back(ho ? paper_ho[k] : paper_cv[k]);
      c.bars[1].y.push_back(100.0 * (ho ? r.at("holdout").at("swapped").at("mean").get<double>()
                                        : (ta.is_object() ? ta.at("mean").get<double>() : ta.get<double>())));
    }
    out.emplace_back(ho ? "fig3-holdout.svg" : "fig4-tenfold.svg", io::svg_bar_chart(c));
  }
  return out;
}

}  // namespace pathref::reproduce
