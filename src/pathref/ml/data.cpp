#include "pathref/ml/data.hpp"

#include "pathref/core/error.hpp"

namespace pathref::ml {

Dataset subset(const Dataset& d, std::span<const std::size_t> indices) {
  Dataset s;
  s.features = d.features;
  s.classes = d.classes;
  s.x.reserve(indices.size() * d.features);
  s.y.reserve(indices.size());
  for (const std::size_t i : indices) {
    require(i < d.rows(), "subset: row index out of range");
    const auto r = d.row(i);
    s.x.insert(s.x.end(), r.begin(), r.end());
    s.y.push_back(d.y[i]);
  }
  return s;
}

}  // namespace pathref::ml
