// Properties of the map_server YAML + PGM reader/writer (spec/formats.md#ros-map-yaml, #pgm,
// #ros-occupancy).
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/io/ros_map.hpp"
#include "support/generators.hpp"

using pathref::io::Occupancy;
using pathref::io::PgmImage;
using pathref::io::RosMapMeta;
using pathref::io::RosMapMode;
using pathref::io::RosMapOptions;
using pathref::io::UnknownAs;

namespace pathref::io {
void showValue(const PgmImage& i, std::ostream& os);
void showValue(const PgmImage& i, std::ostream& os) {
  os << i.width << "x" << i.height << " maxval " << i.maxval << ":";
  for (const auto v : i.pixels) os << " " << v;
}
}  // namespace pathref::io

namespace {

/// A finite double of any magnitude (including subnormals, signed zero), or a "nice" one.
rc::Gen<double> gen_finite() {
  return rc::gen::oneOf(
      rc::gen::map(rc::gen::arbitrary<std::uint64_t>(),
                   [](std::uint64_t bits) {
                     double d = 0.0;
                     static_assert(sizeof d == sizeof bits);
                     std::memcpy(&d, &bits, sizeof d);
                     return std::isfinite(d) ? d : 0.0;
                   }),
      rc::gen::map(rc::gen::inRange(-100000, 100000), [](int k) { return k / 1000.0; }));
}

rc::Gen<PgmImage> gen_image() {
  return rc::gen::exec([] {
    PgmImage img;
    img.width = *rc::gen::inRange<std::int64_t>(1, 12);
    img.height = *rc::gen::inRange<std::int64_t>(1, 12);
    img.maxval = *rc::gen::oneOf(rc::gen::just(255U), rc::gen::just(65535U), rc::gen::just(1U),
                                 rc::gen::inRange(1U, 65536U));
    const std::uint32_t m = img.maxval;
    img.pixels = *rc::gen::container<std::vector<std::uint16_t>>(
        static_cast<std::size_t>(img.width * img.height),
        rc::gen::map(rc::gen::inRange(0U, m + 1), [](std::uint32_t v) { return static_cast<std::uint16_t>(v); }));
    return img;
  });
}

}  // namespace

TEST_CASE("prop: PGM P5 and P2 writers read back identical images", "[ros_map][prop]") {
  rc::prop("parse_pgm(to_pgm_p5(i)) == i and parse_pgm(to_pgm_p2(i)) == i", [] {
    const PgmImage img = *gen_image();
    RC_ASSERT(pathref::io::parse_pgm(pathref::io::to_pgm_p5(img), "a.pgm") == img);
    RC_ASSERT(pathref::io::parse_pgm(pathref::io::to_pgm_p2(img), "b.pgm") == img);
  });
}

TEST_CASE("prop: ROS map writer round trip (grid, resolution, origin exact)", "[ros_map][prop]") {
  rc::prop("parse_ros_map(to_ros_map(g, r, o)) gives back g, r, o under both unknown policies", [] {
    const auto g = *pathref::testing::gen_grid(20, 20, 1.0);
    double res = std::abs(*gen_finite());
    RC_PRE(res > 0.0);
    const std::array<double, 3> origin{*gen_finite(), *gen_finite(), *gen_finite()};
    const auto files = pathref::io::to_ros_map(g, res, origin, "m.pgm");
    for (const UnknownAs u : {UnknownAs::blocked, UnknownAs::free}) {
      const auto back = pathref::io::parse_ros_map(files.yaml, "m.yaml", files.pgm, "m.pgm", RosMapOptions{u, false});
      RC_ASSERT(back.map.grid == g);
      RC_ASSERT(back.meta.resolution == res);
      RC_ASSERT(back.meta.origin == origin);
      RC_ASSERT(std::signbit(back.meta.origin[0]) == std::signbit(origin[0]));
      RC_ASSERT(back.unknown_cells == 0);
    }
  });
}

TEST_CASE("prop: YAML metadata writer round trip", "[ros_map][prop]") {
  rc::prop("parse_ros_yaml(to_ros_yaml(m)) == m", [] {
    RosMapMeta m;
    m.image = *rc::gen::nonEmpty(rc::gen::container<std::string>(rc::gen::inRange<char>(0x20, 0x7f)));
    m.resolution = std::abs(*gen_finite());
    RC_PRE(m.resolution > 0.0);
    m.origin = {*gen_finite(), *gen_finite(), *gen_finite()};
    const double a = *rc::gen::inRange(0, 1001) / 1000.0;
    const double b = *rc::gen::inRange(0, 1001) / 1000.0;
    m.free_thresh = std::min(a, b);
    m.occupied_thresh = std::max(a, b);
    m.mode = *rc::gen::element(RosMapMode::trinary, RosMapMode::scale, RosMapMode::raw);
    m.negate = m.mode != RosMapMode::raw && *rc::gen::arbitrary<bool>();
    const std::string text = pathref::io::to_ros_yaml(m);
    const RosMapMeta back = pathref::io::parse_ros_yaml(text, "m.yaml");
    RC_ASSERT(back == m);
    RC_ASSERT(pathref::io::to_ros_yaml(back) == text);
  });
}

TEST_CASE("prop: occupancy is monotone in the sample and negate mirrors it", "[ros_map][prop]") {
  rc::prop("darker never less occupied; negate(v) == plain(maxval - v)", [] {
    const std::uint32_t maxval = *rc::gen::inRange(1U, 65536U);
    const std::uint32_t v = *rc::gen::inRange(0U, maxval + 1);
    const std::uint32_t w = *rc::gen::inRange(v, maxval + 1);  // w >= v: w is lighter
    RosMapMeta m;
    const double a = *rc::gen::inRange(0, 1001) / 1000.0;
    const double b = *rc::gen::inRange(0, 1001) / 1000.0;
    m.free_thresh = std::min(a, b);
    m.occupied_thresh = std::max(a, b);
    const auto rank = [](Occupancy o) { return o == Occupancy::free ? 0 : o == Occupancy::unknown ? 1 : 2; };
    RC_ASSERT(rank(pathref::io::classify_pixel(v, maxval, m)) >= rank(pathref::io::classify_pixel(w, maxval, m)));
    RosMapMeta n = m;
    n.negate = true;
    RC_ASSERT(pathref::io::classify_pixel(v, maxval, n) == pathref::io::classify_pixel(maxval - v, maxval, m));
  });
}
