#include "pathref/rng/trace.hpp"

#include <algorithm>
#include <cmath>

#include "pathref/core/error.hpp"

namespace pathref::rng {

void Trace::record(std::uint64_t index, double value, std::string_view purpose, std::string_view context) {
  if (draws_.size() >= limit_) {
    ++dropped_;
    return;
  }
  draws_.push_back(Draw{index, value, std::string(purpose), std::string(context)});
}

namespace detail {
void record_draw(Trace& trace, std::uint64_t index, double value, std::string_view purpose, std::string_view context) {
  trace.record(index, value, purpose, context);
}
}  // namespace detail

std::optional<std::size_t> first_divergence(const std::vector<Draw>& a, const std::vector<Draw>& b) {
  const std::size_t n = std::min(a.size(), b.size());
  for (std::size_t k = 0; k < n; ++k)
    if (a[k].value != b[k].value) return k;  // exact: the stream promises bit-for-bit equality
  if (a.size() != b.size()) return n;
  return std::nullopt;
}

}  // namespace pathref::rng
