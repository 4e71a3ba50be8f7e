#pragma once
/// \file mt19937.hpp
/// The one random stream of pathref: MT19937 seeded with init_genrand(seed), doubles by
/// genrand_res53. Same stream as NumPy `RandomState(seed).random_sample()` and MATLAB
/// `rng(seed,'twister'); rand`.
/// Source: Matsumoto & Nishimura (1998), ACM TOMACS 8(1):3-30, doi:10.1145/272991.272995.
/// Spec: rng.stream, rng.res53
#include <cstdint>
#include <random>
#include <span>
#include <string>
#include <string_view>
#include <utility>

namespace pathref::rng {

class Trace;  // trace.hpp
namespace detail {
/// trace.record(index, value, purpose, context), out of line (trace.cpp).
void record_draw(Trace& trace, std::uint64_t index, double value, std::string_view purpose, std::string_view context);
}  // namespace detail

/// The MT19937 engine of the standard library with 32-bit words: exactly the parameters of
/// [rand.predef]'s `std::mt19937` (w = 32, n = 624, m = 397, r = 31, a = 0x9908B0DF, u = 11,
/// d = 0xFFFFFFFF, s = 7, b = 0x9D2C5680, t = 15, c = 0xEFC60000, l = 18, f = 1812433253),
/// but with `std::uint32_t` as its word type instead of `std::uint_fast32_t`. [rand.eng.mers]
/// defines the outputs from w-bit arithmetic only, so both produce the same stream bit for bit
/// (tests/prop/rng_prop.cpp compares them); with 32-bit words libstdc++'s state refill
/// vectorises (≈ 4x fewer cycles per output on x86-64, docs/performance.md).
/// Spec: rng.stream
using Mt19937 = std::mersenne_twister_engine<std::uint32_t, 32, 624, 397, 31, 0x9908B0DFU, 11,
                                             0xFFFFFFFFU, 7, 0x9D2C5680U, 15, 0xEFC60000U, 18,
                                             1812433253U>;

/// Converts two consecutive 32-bit MT19937 outputs to a double in [0, 1) with 53 random bits:
/// ((a >> 5) * 67108864 + (b >> 6)) / 2^53.
/// Spec: rng.res53. Post: result in [0, 1), a multiple of 2^-53. Golden: golden/rng/rng.res53.json
[[nodiscard]] constexpr double res53(std::uint32_t a, std::uint32_t b) noexcept {
  const std::uint64_t hi = static_cast<std::uint64_t>(a >> 5U);
  const std::uint64_t lo = static_cast<std::uint64_t>(b >> 6U);
  return static_cast<double>(hi * 67108864ULL + lo) * (1.0 / 9007199254740992.0);
}

/// The reference stream: MT19937 seeded with init_genrand(seed). Owns its state; counts the
/// doubles drawn so that traces can say "draw #k".
/// Spec: rng.stream. Golden: golden/rng/rng.stream.json
class Stream {
 public:
  /// init_genrand(seed). The engine (Mt19937) is specified bit-for-bit by [rand.eng.mers], and
  /// its seeding constructor is exactly init_genrand.
  explicit Stream(std::uint32_t seed) : engine_(seed), seed_(seed) {}

  /// The next 32-bit output (genrand_int32).
  /// Spec: rng.stream
  [[nodiscard]] std::uint32_t next_u32() { return static_cast<std::uint32_t>(engine_()); }

  /// The next double in [0, 1) (genrand_res53): consumes two 32-bit outputs. `purpose` names
  /// the rule that consumes it (recorded only when a trace is attached: spec/rng.md#draw-traces).
  /// Spec: rng.res53. Post: a multiple of 2^-53 in [0, 1). Golden: golden/rng/rng.res53.json
  [[nodiscard]] double next_double(std::string_view purpose = {}) {
    const std::uint32_t a = next_u32();
    const std::uint32_t b = next_u32();
    const double u = res53(a, b);
    if (trace_ != nullptr) [[unlikely]]
      detail::record_draw(*trace_, doubles_drawn_, u, purpose, context_);
    ++doubles_drawn_;
    return u;
  }
  /// Attaches a trace (not owned; nullptr detaches): every later next_double is recorded in it.
  void set_trace(Trace* trace) noexcept { trace_ = trace; }
  [[nodiscard]] bool tracing() const noexcept { return trace_ != nullptr; }
  /// Where the caller is ("iteration 2 ant 5 step 7"), recorded with the following draws. Callers
  /// build the text only when tracing() is true, so an untraced run pays nothing for it.
  void set_context(std::string context) { context_ = std::move(context); }

  [[nodiscard]] std::uint32_t seed() const noexcept { return seed_; }
  [[nodiscard]] std::uint64_t doubles_drawn() const noexcept { return doubles_drawn_; }

 private:
  Mt19937 engine_;
  std::uint32_t seed_;
  std::uint64_t doubles_drawn_ = 0;
  Trace* trace_ = nullptr;
  std::string context_;
};

}  // namespace pathref::rng
