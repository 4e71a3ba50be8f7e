// Fuzz target: map_server YAML metadata reader and writer (spec/formats.md#ros-map-yaml).
//
// INVARIANT: for every byte string t, parse_ros_yaml(t) (strict) and
// parse_ros_yaml(t, allow_unknown_keys) either return RosMapMeta or throw pathref::ParseError
// (nothing else, no UB). If the strict reader accepts t, the lenient one accepts it with the
// same result. When the lenient reader returns m, to_ros_yaml(m) does not throw, is accepted by
// the strict reader, reads back == m, and is a fixed point of write-after-read.
// A broken invariant traps (__builtin_trap); sanitizers catch the rest.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "pathref/core/error.hpp"
#include "pathref/io/ros_map.hpp"

namespace {
std::optional<pathref::io::RosMapMeta> parse(std::string_view text, bool lenient) {
  try {
    return pathref::io::parse_ros_yaml(text, "fuzz.yaml", lenient);
  } catch (const pathref::ParseError&) {
    return std::nullopt;
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto strict = parse(text, false);
  const auto lenient = parse(text, true);
  if (strict && !(lenient && *lenient == *strict)) __builtin_trap();
  if (!lenient) return 0;
  const std::string written = pathref::io::to_ros_yaml(*lenient);
  const pathref::io::RosMapMeta again = pathref::io::parse_ros_yaml(written, "written.yaml");
  if (!(again == *lenient)) __builtin_trap();
  if (pathref::io::to_ros_yaml(again) != written) __builtin_trap();
  return 0;
}
