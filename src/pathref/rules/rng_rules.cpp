// JSON adapters for the rng.* rules (spec/rng.md).
#include <cstdint>

#include "pathref/core/error.hpp"
#include "pathref/rng/draws.hpp"
#include "pathref/rng/mt19937.hpp"
#include "pathref/rules/modules.hpp"

namespace pathref::rules {

namespace {
std::uint32_t seed_arg(const Json& in) {
  const long long s = arg_integer(in, "seed");
  require(s >= 0 && s <= 0xFFFFFFFFLL, "seed must be a 32-bit unsigned integer");
  return static_cast<std::uint32_t>(s);
}
std::size_t count_arg(const Json& in, const char* key, long long max) {
  const long long n = arg_integer(in, key);
  require(n >= 0 && n <= max, std::string(key) + " out of range");
  return static_cast<std::size_t>(n);
}
}  // namespace

void register_rng_rules(Registry& r) {
  r.add(Rule{
      "rng.stream",
      "First 32-bit outputs of MT19937 seeded with init_genrand(seed)",
      "pathref::rng::Stream::next_u32",
      {{"seed", "integer", "32-bit unsigned seed"}, {"count", "integer", "number of outputs (<= 10000)"}},
      {{"u32", "integer[]", "genrand_int32 outputs in order"},
       {"last", "integer", "the last output (the count-th)"}},
      [](const Json& in) {
        rng::Stream s(seed_arg(in));
        Json out = Json::array();
        const std::size_t n = count_arg(in, "count", 10000);
        require(n >= 1, "count must be at least 1");
        for (std::size_t i = 0; i < n; ++i) out.push_back(s.next_u32());
        return Json{{"u32", out}, {"last", out.back()}};
      }});
  r.add(Rule{
      "rng.res53",
      "Doubles in [0,1) by genrand_res53 from the MT19937 stream",
      "pathref::rng::Stream::next_double",
      {{"seed", "integer", "32-bit unsigned seed"}, {"count", "integer", "number of doubles (<= 10000)"},
       {"skip", "integer", "doubles to discard first (optional, default 0)"}},
      {{"u", "number[]", "the doubles in order"}},
      [](const Json& in) {
        rng::Stream s(seed_arg(in));
        const std::size_t skip = in.contains("skip") ? count_arg(in, "skip", 10000000) : 0;
        for (std::size_t i = 0; i < skip; ++i) (void)s.next_double();
        Json out = Json::array();
        const std::size_t n = count_arg(in, "count", 10000);
        for (std::size_t i = 0; i < n; ++i) out.push_back(s.next_double());
        return Json{{"u", out}};
      }});
  r.add(Rule{
      "rng.index",
      "Integer in [0,n) from a uniform draw: floor(u*n)",
      "pathref::rng::uniform_index",
      {{"u", "number", "draw in [0,1)"}, {"n", "integer", "n >= 1"}},
      {{"k", "integer", "index in [0,n)"}},
      [](const Json& in) {
        const long long n = arg_integer(in, "n");
        require(n >= 1, "n must be at least 1");
        return Json{{"k", rng::uniform_index(arg_number(in, "u"), static_cast<std::size_t>(n))}};
      }});
  r.add(Rule{
      "rng.roulette",
      "Roulette choice: first k with w_k > 0 and cumsum_k >= u*sum(w)",
      "pathref::rng::roulette",
      {{"weights", "number[]", "non-negative weights, positive sum"}, {"u", "number", "draw in [0,1)"}},
      {{"k", "integer", "chosen index (0-based)"}},
      [](const Json& in) {
        const auto w = arg_numbers(in, "weights");
        return Json{{"k", rng::roulette(w, arg_number(in, "u"))}};
      }});
  r.add(Rule{
      "rng.bernoulli",
      "Bernoulli(p) from a uniform draw: u < p",
      "pathref::rng::bernoulli",
      {{"u", "number", "draw in [0,1)"}, {"p", "number", "probability in [0,1]"}},
      {{"b", "bool", "u < p"}},
      [](const Json& in) {
        return Json{{"b", rng::bernoulli(arg_number(in, "u"), arg_number(in, "p"))}};
      }});
}

}  // namespace pathref::rules
