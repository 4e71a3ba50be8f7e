// spec: rng.stream, rng.res53, rng.index, rng.roulette, rng.bernoulli
#include <catch2/catch.hpp>

#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/rng/draws.hpp"
#include "pathref/rng/mt19937.hpp"

using namespace pathref;

TEST_CASE("rng.stream: known outputs of mt19937ar", "[rng]") {
  // The C++ standard ([rand.predef]) pins the 10000th output of mt19937 seeded 5489.
  rng::Stream s(5489);
  std::uint32_t v = 0;
  for (int i = 0; i < 10000; ++i) v = s.next_u32();
  CHECK(v == 4123659995U);
}

TEST_CASE("rng.res53: NumPy RandomState(42).random_sample() first value", "[rng]") {
  rng::Stream s(42);
  CHECK(s.next_double() == 0.3745401188473625);
  CHECK(s.doubles_drawn() == 1);
}

TEST_CASE("rng.res53: extremes of the conversion", "[rng]") {
  CHECK(rng::res53(0, 0) == 0.0);
  CHECK(rng::res53(0xFFFFFFFFU, 0xFFFFFFFFU) == 1.0 - 0x1p-53);
}

TEST_CASE("rng: preconditions raise DomainError", "[rng]") {
  const std::vector<double> none;
  const std::vector<double> zeros{0.0, 0.0};
  const std::vector<double> neg{1.0, -1.0};
  CHECK_THROWS_AS(rng::uniform_index(1.0, 3), DomainError);
  CHECK_THROWS_AS(rng::uniform_index(-0.1, 3), DomainError);
  CHECK_THROWS_AS(rng::uniform_index(0.5, 0), DomainError);
  CHECK_THROWS_AS(rng::roulette(none, 0.5), DomainError);
  CHECK_THROWS_AS(rng::roulette(zeros, 0.5), DomainError);
  CHECK_THROWS_AS(rng::roulette(neg, 0.5), DomainError);
  CHECK_THROWS_AS(rng::bernoulli(0.5, 1.5), DomainError);
}

TEST_CASE("rng.roulette: u = 0 skips leading zero weights", "[rng]") {
  const std::vector<double> w{0.0, 0.0, 2.0, 1.0};
  CHECK(rng::roulette(w, 0.0) == 2);
  CHECK(rng::roulette(w, 0.999999) == 3);
  CHECK(rng::roulette(w, 2.0 / 3.0) == 2);  // cumsum 2 >= (2/3)*3 = 2: boundary goes left
}
