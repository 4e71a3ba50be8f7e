#pragma once
/// \file trace.hpp
/// Draw traces (spec/rng.md#draw-traces): every double a traced rng::Stream hands out, in order,
/// with its 0-based index, its value and its purpose (the rule that consumed it, e.g.
/// "aco.transition q0 test") in the context the planner set (e.g. "iteration 2 ant 5 step 7").
/// Written as JSON lines by `pathref plan --trace FILE`; `pathref trace-diff A B` names the first
/// draw where two traces disagree. A user's NumPy or MATLAB implementation writes the same format
/// (docs/rng.md) to find where its replay of a seeded run leaves pathref's.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace pathref::rng {

/// One draw of a traced stream.
struct Draw {
  std::uint64_t index = 0;  ///< 0-based: the stream's index-th double (genrand_res53 call)
  double value = 0.0;       ///< the double, in [0, 1)
  std::string purpose;      ///< the rule that consumed it ("" when the caller did not say)
  std::string context;      ///< where the planner was ("" when it did not say)
};

/// The draws of one run, in order. Recording stops silently after `limit` draws and counts
/// the rest (`dropped`), so a trace of a long run cannot exhaust memory.
class Trace {
 public:
  explicit Trace(std::size_t limit = 10'000'000) : limit_(limit) {}
  void record(std::uint64_t index, double value, std::string_view purpose, std::string_view context);
  [[nodiscard]] const std::vector<Draw>& draws() const noexcept { return draws_; }
  [[nodiscard]] std::uint64_t dropped() const noexcept { return dropped_; }

 private:
  std::size_t limit_;
  std::vector<Draw> draws_;
  std::uint64_t dropped_ = 0;
};

// Writing and reading trace files (JSON lines) is io's: pathref/io/trace_file.hpp (io::trace_text,
// io::parse_trace; docs/architecture.md#layers). Before 0.3.0 they were rng::trace_text and
// rng::parse_trace.

/// Where two traces part: the first index at which the values differ or one trace ends
/// (nullopt when they are equal draw for draw). Purposes and contexts are not compared (a
/// user's labels need not match pathref's); they are shown to say what each side was doing.
[[nodiscard]] std::optional<std::size_t> first_divergence(const std::vector<Draw>& a, const std::vector<Draw>& b);

}  // namespace pathref::rng
