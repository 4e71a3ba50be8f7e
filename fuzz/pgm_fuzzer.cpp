// Fuzz target: PGM reader (P2 and P5) and writers, and the map_server occupancy conversion
// (spec/formats.md#pgm, spec/formats.md#ros-occupancy).
//
// INVARIANT: for every byte string b, parse_pgm(b) either returns an image or throws
// pathref::ParseError (nothing else, no UB, memory bounded by about 2|b|). A returned image i
// has width*height samples, each <= maxval; parse_pgm(to_pgm_p5(i)) == i and
// parse_pgm(to_pgm_p2(i)) == i. ros_map_from_image(i, meta) gives a width x height grid for
// trinary and scale (both unknown policies, negate or not) and, when maxval == 255, for raw;
// each cell is blocked exactly when classify_pixel says occupied, or unknown under
// unknown=blocked, and the unknown count is the same under both policies.
// A broken invariant traps (__builtin_trap); sanitizers catch the rest.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "pathref/core/error.hpp"
#include "pathref/io/ros_map.hpp"

using pathref::io::Occupancy;
using pathref::io::PgmImage;
using pathref::io::RosMapMeta;
using pathref::io::RosMapMode;
using pathref::io::RosMapOptions;
using pathref::io::UnknownAs;

namespace {
void check_conversion(const PgmImage& img, const RosMapMeta& meta) {
  const auto blocked = pathref::io::ros_map_from_image(img, meta, RosMapOptions{UnknownAs::blocked, false}, "f.pgm");
  const auto freed = pathref::io::ros_map_from_image(img, meta, RosMapOptions{UnknownAs::free, false}, "f.pgm");
  if (blocked.map.grid.width() != img.width || blocked.map.grid.height() != img.height) __builtin_trap();
  if (blocked.unknown_cells != freed.unknown_cells) __builtin_trap();
  std::int64_t unknown = 0;
  for (std::int64_t row = 0; row < img.height; ++row)
    for (std::int64_t x = 0; x < img.width; ++x) {
      const auto v = img.pixels[static_cast<std::size_t>(row * img.width + x)];
      const Occupancy o = pathref::io::classify_pixel(v, img.maxval, meta);
      const pathref::grid::Cell c{x, img.height - 1 - row};
      unknown += o == Occupancy::unknown ? 1 : 0;
      if (blocked.map.grid.blocked(c) != (o != Occupancy::free)) __builtin_trap();
      if (freed.map.grid.blocked(c) != (o == Occupancy::occupied)) __builtin_trap();
    }
  if (unknown != blocked.unknown_cells) __builtin_trap();
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  PgmImage img;
  try {
    img = pathref::io::parse_pgm(bytes, "fuzz.pgm");
  } catch (const pathref::ParseError&) {
    return 0;
  }
  if (img.pixels.size() != static_cast<std::size_t>(img.width * img.height)) __builtin_trap();
  for (const auto v : img.pixels)
    if (v > img.maxval) __builtin_trap();
  if (!(pathref::io::parse_pgm(pathref::io::to_pgm_p5(img), "p5.pgm") == img)) __builtin_trap();
  if (!(pathref::io::parse_pgm(pathref::io::to_pgm_p2(img), "p2.pgm") == img)) __builtin_trap();

  RosMapMeta meta;  // map_saver's thresholds 0.65 / 0.196
  for (const RosMapMode mode : {RosMapMode::trinary, RosMapMode::scale, RosMapMode::raw})
    for (const bool negate : {false, true}) {
      if (mode == RosMapMode::raw && (negate || img.maxval != 255)) continue;
      meta.mode = mode;
      meta.negate = negate;
      check_conversion(img, meta);
    }
  meta.mode = RosMapMode::raw;
  meta.negate = false;
  if (img.maxval != 255) {
    try {
      (void)pathref::io::ros_map_from_image(img, meta, RosMapOptions{}, "f.pgm");
      __builtin_trap();  // raw needs maxval 255
    } catch (const pathref::ParseError&) {
    }
  }
  return 0;
}
