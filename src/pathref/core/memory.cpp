#include "pathref/core/memory.hpp"

#include <fmt/core.h>

#include <cctype>
#include <limits>

#include "pathref/core/error.hpp"

namespace pathref::memory {

std::uint64_t parse_size(std::string_view text, std::string_view option) {
  const auto bad = [&] {
    return UsageError(fmt::format("{} expects a size in bytes with an optional suffix K, M, G or T "
                                  "(powers of 1024), from 1M to 2^62 bytes, e.g. 512M or 4G; got '{}'",
                                  option, text));
  };
  std::size_t i = 0;
  std::uint64_t v = 0;
  while (i < text.size() && text[i] >= '0' && text[i] <= '9') {
    if (i >= 19) throw bad();  // more than 19 digits: beyond 2^62 anyway
    v = v * 10 + static_cast<std::uint64_t>(text[i] - '0');
    ++i;
  }
  if (i == 0) throw bad();
  std::string suffix;
  for (std::size_t k = i; k < text.size(); ++k)
    suffix.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(text[k]))));
  int shift = 0;
  if (suffix.empty() || suffix == "B") shift = 0;
  else if (suffix == "K" || suffix == "KB" || suffix == "KIB") shift = 10;
  else if (suffix == "M" || suffix == "MB" || suffix == "MIB") shift = 20;
  else if (suffix == "G" || suffix == "GB" || suffix == "GIB") shift = 30;
  else if (suffix == "T" || suffix == "TB" || suffix == "TIB") shift = 40;
  else throw bad();
  constexpr std::uint64_t max = std::uint64_t{1} << 62;
  if (v > (max >> shift)) throw bad();
  v <<= shift;
  if (v < min_limit) throw bad();
  return v;
}

std::string show_bytes(std::uint64_t bytes) {
  const double b = static_cast<double>(bytes);
  if (bytes >= (std::uint64_t{1} << 30)) return fmt::format("{} bytes ({:.1f} GiB)", bytes, b / 1073741824.0);
  if (bytes >= (std::uint64_t{1} << 20)) return fmt::format("{} bytes ({:.1f} MiB)", bytes, b / 1048576.0);
  if (bytes >= (std::uint64_t{1} << 10)) return fmt::format("{} bytes ({:.1f} KiB)", bytes, b / 1024.0);
  return fmt::format("{} bytes", bytes);
}

std::uint64_t times(std::uint64_t count, std::uint64_t bytes_each) noexcept {
  if (bytes_each != 0 && count > std::numeric_limits<std::uint64_t>::max() / bytes_each)
    return std::numeric_limits<std::uint64_t>::max();
  return count * bytes_each;
}

std::uint64_t plus(std::uint64_t a, std::uint64_t b) noexcept {
  return a > std::numeric_limits<std::uint64_t>::max() - b ? std::numeric_limits<std::uint64_t>::max() : a + b;
}

void require_within(std::uint64_t estimate, std::uint64_t limit, std::string_view what) {
  if (estimate <= limit) return;
  throw UsageError(fmt::format("{} needs an estimated {}, more than the memory limit of {}; raise the "
                               "limit with --max-memory SIZE or give a smaller input (spec/cli.md#memory)",
                               what, show_bytes(estimate), show_bytes(limit)));
}

}  // namespace pathref::memory
