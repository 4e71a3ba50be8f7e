#pragma once
// Internal to pathref_geometry (includes CGAL): the exact rational value of a Decimal in CGAL's
// Epeck exact number type. Shared by the CGAL translation units (inflation_cgal.cpp,
// obstacles_cgal.cpp); never included by a public header.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <algorithm>
#include <string>

#include "pathref/geometry/decimal.hpp"

namespace pathref::geometry::exact_detail {

using ET = CGAL::Epeck::FT::ET;

/// The exact rational value of a Decimal.
inline ET exact(const Decimal& d) {
  ET acc(0);
  const std::string& ds = d.digits;
  for (std::size_t i = 0; i < ds.size(); i += 9) {
    const std::size_t n = std::min<std::size_t>(9, ds.size() - i);
    int chunk = 0, scale = 1;
    for (std::size_t k = 0; k < n; ++k) {
      chunk = chunk * 10 + (ds[i + k] - '0');
      scale *= 10;
    }
    acc = acc * ET(scale) + ET(chunk);
  }
  ET p(1);
  for (std::int32_t k = 0; k < (d.exp10 < 0 ? -d.exp10 : d.exp10); ++k) p = p * ET(10);
  ET v = d.exp10 >= 0 ? ET(acc * p) : ET(acc / p);
  return d.negative ? ET(-v) : v;
}

}  // namespace pathref::geometry::exact_detail
