// Fuzz target: the UCI wall-following data reader of cin2021's ML model
// (spec/cin2021-ml.md#r[cin2021.data]).
//
// INVARIANT: for every byte string t, parse_wall_following(t) either returns a Dataset d or throws
// pathref::ParseError (never another exception, never UB). When it returns: d has >= 1 row and
// 1..64 features, x holds rows * features finite values, every label is in [0, 4); printing d
// with %.17g and the label names (LF line ends) and reading it back gives d again; reading t with
// max_rows = 4 gives the same d when it has <= 4 rows and throws ParseError otherwise.
// A broken invariant traps (__builtin_trap); sanitizers catch the rest.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>

#include "pathref/io/wall_following.hpp"
#include "pathref/core/error.hpp"
#include "pathref/ml/data.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace pathref::ml;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::optional<Dataset> d;
  try {
    d = pathref::io::parse_wall_following(text, "fuzz.data");
  } catch (const pathref::ParseError&) {
    return 0;
  }
  if (d->rows() < 1 || d->features < 1 || d->features > 64 || d->x.size() != d->rows() * d->features) __builtin_trap();
  std::string out;
  for (std::size_t i = 0; i < d->rows(); ++i) {
    if (d->y[i] < 0 || d->y[i] >= 4) __builtin_trap();
    for (const double v : d->row(i)) {
      if (!std::isfinite(v)) __builtin_trap();
      char buf[40];
      std::snprintf(buf, sizeof buf, "%.17g,", v);
      out += buf;
    }
    out += std::string(wall_following_labels[static_cast<std::size_t>(d->y[i])]) + "\n";
  }
  const Dataset r = pathref::io::parse_wall_following(out, "printed.data");
  if (r.x != d->x || r.y != d->y || r.features != d->features) __builtin_trap();
  pathref::io::DataLimits small;
  small.max_rows = 4;
  try {
    const Dataset s = pathref::io::parse_wall_following(text, "fuzz.data", small);
    if (d->rows() > 4 || s.x != d->x || s.y != d->y) __builtin_trap();
  } catch (const pathref::ParseError&) {
    if (d->rows() <= 4) __builtin_trap();
  }
  return 0;
}
