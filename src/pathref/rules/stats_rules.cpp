// JSON adapters for the stats.* rules (spec/stats.md): the statistics and claim judgements of the
// reproductions (src/pathref/reproduce/stats.hpp).
#include "pathref/core/error.hpp"
#include "pathref/reproduce/stats.hpp"
#include "pathref/rules/modules.hpp"

namespace pathref::rules {

namespace {
using namespace pathref::reproduce;

/// An array of numbers where "inf", "-inf", "nan" stand for the non-finite values (so that golden
/// vectors can reach the DomainErrors).
std::vector<double> values_arg(const Json& in, const char* key) {
  const Json& v = arg(in, key);
  if (!v.is_array()) throw UsageError(std::string("input '") + key + "' must be an array");
  std::vector<double> out;
  out.reserve(v.size());
  Json one = Json::object();
  for (const Json& e : v) {
    one["v"] = e;
    out.push_back(arg_number(one, "v"));
  }
  return out;
}

std::size_t resamples_arg(const Json& in) {
  if (!in.contains("resamples")) return 2000;
  const long long b = arg_integer(in, "resamples");
  if (b < 1 || b > 1000000) throw DomainError("resamples must lie in [1, 10^6]");
  return static_cast<std::size_t>(b);
}

std::uint32_t seed_arg(const Json& in) {
  const long long s = arg_integer(in, "seed");
  if (s < 0 || s > 4294967295LL) throw UsageError("input 'seed' must lie in [0, 2^32 - 1]");
  return static_cast<std::uint32_t>(s);
}

Sense sense_arg(const Json& in) {
  const std::string s = opt_string(in, "sense", "lower_is_better");
  if (s == "lower_is_better") return Sense::lower_is_better;
  if (s == "higher_is_better") return Sense::higher_is_better;
  throw UsageError("input 'sense' must be lower_is_better or higher_is_better");
}

Direction observed_arg(const Json& in) {
  const std::string s = arg_string(in, "observed");
  if (s == "as_claimed") return Direction::as_claimed;
  if (s == "opposite") return Direction::opposite;
  if (s == "equal") return Direction::equal;
  throw UsageError("input 'observed' must be as_claimed, opposite or equal");
}

Claimed claim_arg(const Json& in) {
  const std::string s = opt_string(in, "claim", "a_less");
  if (s == "a_less") return Claimed::a_less;
  if (s == "a_greater") return Claimed::a_greater;
  throw UsageError("input 'claim' must be a_less or a_greater");
}

std::string direction_name(Direction d) {
  switch (d) {
    case Direction::none: return "none";
    case Direction::pathref_better: return "pathref_better";
    case Direction::pathref_worse: return "pathref_worse";
    case Direction::as_claimed: return "as_claimed";
    case Direction::opposite: return "opposite";
    case Direction::equal: return "equal";
  }
  return "none";
}

std::string verdict_name(Verdict v) {
  switch (v) {
    case Verdict::holds: return "holds";
    case Verdict::fails: return "fails";
    case Verdict::not_significant: return "not_significant";
    case Verdict::inconclusive: return "inconclusive";
    case Verdict::untestable: return "untestable";
  }
  return "untestable";
}

Json judgement_out(const Judgement& j) {
  return Json{{"verdict", verdict_name(j.verdict)},
              {"direction", direction_name(j.direction)},
              {"text", verdict_text(j.verdict, j.direction)}};
}
}  // namespace

void register_stats_rules(Registry& r) {
  r.add(Rule{"stats.mean",
             "Arithmetic mean, summed left to right",
             "pathref::reproduce::mean",
             {{"values", "number[]", "n >= 1, finite"}},
             {{"mean", "number", "sum / n"}},
             [](const Json& in) { return Json{{"mean", number(mean(values_arg(in, "values")))}}; }});
  r.add(Rule{"stats.sd",
             "Sample standard deviation (n - 1), two passes",
             "pathref::reproduce::sample_std",
             {{"values", "number[]", "n >= 2, finite"}},
             {{"sd", "number", ">= 0"}},
             [](const Json& in) { return Json{{"sd", number(sample_std(values_arg(in, "values")))}}; }});
  r.add(Rule{"stats.quantile",
             "Type-7 quantile (NumPy's default) of a sample",
             "pathref::reproduce::quantile",
             {{"values", "number[]", "n >= 1, finite, any order"}, {"p", "number", "in [0, 1]"}},
             {{"quantile", "number", "x_j + (h - j)(x_{j+1} - x_j), h = (n - 1) p"}},
             [](const Json& in) {
               return Json{{"quantile", number(quantile(values_arg(in, "values"), arg_number(in, "p")))}};
             }});
  r.add(Rule{"stats.bootstrap_ci",
             "Seeded percentile bootstrap interval (rng::Stream, stated draw order)",
             "pathref::reproduce::bootstrap_ci, pathref::reproduce::bootstrap_two_sample_ci, "
             "pathref::reproduce::bootstrap_paired_ci",
             {{"a", "number[]", "n_a >= 2, finite"},
              {"b", "number[]", "two-sample statistics only: n_b >= 2, finite (paired: n_b = n_a)"},
              {"paired", "boolean", "default false; true: the pairs (a_i, b_i) are resampled together"},
              {"statistic", "string",
               "mean (default) | minimum | mean_difference | reduction_percent | sd_difference"},
              {"seed", "integer", "the stream's seed"},
              {"resamples", "integer", "B, default 2000"},
              {"level", "number", "confidence level, default 0.95"}},
             {{"lo", "number", "Q(alpha / 2) of the sorted replicates"},
              {"hi", "number", "Q(1 - alpha / 2)"}},
             [](const Json& in) {
               BootstrapOptions o;
               o.seed = seed_arg(in);
               o.resamples = resamples_arg(in);
               o.level = in.contains("level") ? arg_number(in, "level") : 0.95;
               const BootStatistic s = parse_boot_statistic(opt_string(in, "statistic", "mean"));
               const bool paired = in.contains("paired") && in.at("paired").is_boolean() && in.at("paired").get<bool>();
               if (in.contains("paired") && !in.at("paired").is_boolean())
                 throw UsageError("stats.bootstrap_ci: 'paired' must be true or false");
               const Interval ci = paired ? bootstrap_paired_ci(values_arg(in, "a"), values_arg(in, "b"), s, o)
                                   : (s == BootStatistic::mean || s == BootStatistic::minimum)
                                       ? bootstrap_ci(values_arg(in, "a"), s, o)
                                       : bootstrap_two_sample_ci(values_arg(in, "a"), values_arg(in, "b"), s, o);
               return Json{{"lo", number(ci.lo)}, {"hi", number(ci.hi)}};
             }});
  r.add(Rule{"stats.betainc",
             "Regularized incomplete beta function I_x(a, b)",
             "pathref::reproduce::betainc",
             {{"a", "number", "> 0"}, {"b", "number", "> 0"}, {"x", "number", "in [0, 1]"}},
             {{"value", "number", "in [0, 1]"}},
             [](const Json& in) {
               return Json{{"value", number(betainc(arg_number(in, "a"), arg_number(in, "b"), arg_number(in, "x")))}};
             }});
  r.add(Rule{"stats.student_t",
             "Two-sided p value of Student's t with df degrees of freedom",
             "pathref::reproduce::student_t_two_sided_p",
             {{"t", "number", "not NaN"}, {"df", "number", "> 0, finite"}},
             {{"p", "number", "P(|T| >= |t|)"}},
             [](const Json& in) {
               return Json{{"p", number(student_t_two_sided_p(arg_number(in, "t"), arg_number(in, "df")))}};
             }});
  r.add(Rule{"stats.mann_whitney",
             "Mann-Whitney U test, two-sided (SciPy's method='auto', continuity and tie corrections)",
             "pathref::reproduce::mann_whitney",
             {{"a", "number[]", "n_a >= 1, finite"}, {"b", "number[]", "n_b >= 1, finite"}},
             {{"u_a", "number", "R_a - n_a (n_a + 1) / 2"},
              {"u_b", "number", "n_a n_b - u_a"},
              {"exact", "bool", "exact null distribution (min(n) <= 8, no ties)"},
              {"z", "number", "normal approximation only (absent when exact or sigma = 0)"},
              {"p", "number", "two-sided p value"}},
             [](const Json& in) {
               const MannWhitney m = mann_whitney(values_arg(in, "a"), values_arg(in, "b"));
               Json out{{"u_a", number(m.u_a)}, {"u_b", number(m.u_b)}, {"exact", m.exact}, {"p", number(m.p)}};
               if (m.z) out["z"] = number(*m.z);
               return out;
             }});
  r.add(Rule{"stats.welch",
             "Welch's unequal-variance t test, two-sided",
             "pathref::reproduce::welch",
             {{"a", "number[]", "n_a >= 2, finite"}, {"b", "number[]", "n_b >= 2, finite"}},
             {{"mean_difference", "number", "mean(a) - mean(b)"},
              {"t", "number", "Welch's t (+-inf or 0 when both samples are constant)"},
              {"df", "number", "Welch-Satterthwaite df (absent when both samples are constant)"},
              {"p", "number", "two-sided p value"}},
             [](const Json& in) {
               const Welch w = welch(values_arg(in, "a"), values_arg(in, "b"));
               Json out{{"mean_difference", number(w.mean_difference)}, {"t", number(w.t)}, {"p", number(w.p)}};
               if (w.df) out["df"] = number(*w.df);
               return out;
             }});
  r.add(Rule{"stats.margin",
             "Equivalence margin of a claimed value by kind of quantity",
             "pathref::reproduce::equivalence_margin",
             {{"quantity", "string", "length | turns | iterations | time | percent"},
              {"paper", "number", "the paper's value, finite"}},
             {{"margin", "number", ">= 0"}},
             [](const Json& in) {
               return Json{{"margin", number(equivalence_margin(parse_quantity(arg_string(in, "quantity")),
                                                                arg_number(in, "paper")))}};
             }});
  r.add(Rule{"stats.equivalence",
             "Verdict on a claimed value: interval within paper +- margin",
             "pathref::reproduce::judge_equivalence",
             {{"lo", "number", "interval low end"},
              {"hi", "number", "interval high end, >= lo"},
              {"paper", "number", "the paper's value"},
              {"margin", "number", ">= 0"},
              {"sense", "string", "lower_is_better (default) | higher_is_better"}},
             {{"verdict", "string", "holds | fails | inconclusive"},
              {"direction", "string", "none | pathref_better | pathref_worse"},
              {"text", "string", "as the reports print it"}},
             [](const Json& in) {
               return judgement_out(judge_equivalence(Interval{arg_number(in, "lo"), arg_number(in, "hi")},
                                                      arg_number(in, "paper"), arg_number(in, "margin"),
                                                      sense_arg(in)));
             }});
  r.add(Rule{"stats.compare",
             "Verdict on a comparison: from (p, alpha, observed), from an interval of a - b, or from samples",
             "pathref::reproduce::judge_comparison, pathref::reproduce::judge_interval_comparison, "
             "pathref::reproduce::compare_samples",
             {{"p", "number", "mode 1: the two-sided p value"},
              {"alpha", "number", "modes 1 and 3: significance level, default 0.05"},
              {"observed", "string", "mode 1: as_claimed | opposite | equal"},
              {"lo", "number", "mode 2: interval of a - b, low end"},
              {"hi", "number", "mode 2: high end"},
              {"a", "number[]", "mode 3: runs of A (Mann-Whitney decides)"},
              {"b", "number[]", "mode 3: runs of B"},
              {"claim", "string", "modes 2 and 3: a_less (default) | a_greater"}},
             {{"verdict", "string", "holds | fails | not_significant"},
              {"direction", "string", "as_claimed | opposite | equal"},
              {"text", "string", "as the reports print it"}},
             [](const Json& in) {
               const double alpha = in.contains("alpha") ? arg_number(in, "alpha") : 0.05;
               if (in.contains("a") || in.contains("b")) {
                 const auto c = compare_samples(values_arg(in, "a"), values_arg(in, "b"), claim_arg(in), alpha);
                 Json out = judgement_out(c.judgement);
                 out["p"] = number(c.mann_whitney.p);
                 return out;
               }
               if (in.contains("lo") || in.contains("hi"))
                 return judgement_out(judge_interval_comparison(
                     Interval{arg_number(in, "lo"), arg_number(in, "hi")}, claim_arg(in)));
               return judgement_out(judge_comparison(arg_number(in, "p"), alpha, observed_arg(in)));
             }});
}

}  // namespace pathref::rules
