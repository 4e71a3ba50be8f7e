// Uses the installed pathref: the first double of seed 42 must be NumPy's 0.3745401188473625.
#include <cstdio>

#include "pathref/grid/grid.hpp"
#include "pathref/rng/mt19937.hpp"

int main() {
  pathref::rng::Stream s(42);
  const double u = s.next_double();
  const pathref::grid::Grid g(3, 2);
  if (u != 0.3745401188473625 || g.cell_count() != 6) {
    std::puts("consumer: unexpected result");
    return 1;
  }
  std::puts("consumer: ok");
  return 0;
}
