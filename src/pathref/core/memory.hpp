#pragma once
/// \file memory.hpp
/// Memory budgets (spec/cli.md#memory): a run's need is estimated from the sizes of its data
/// structures before they are allocated, and what grows during a run (the colony's and the GA's
/// stored paths) is counted as it grows; past the limit the run stops with a UsageError that
/// names the estimate and the limit, never a slow death. `--max-memory` sets the limit.
/// Spec: spec/cli.md#memory (the limit, its default, which limit decides), spec/formats.md#limits
/// (each reader's bytes per cell / per node), the planner specs (bytes per cell of each planner).
#include <cstdint>
#include <string>
#include <string_view>

namespace pathref::memory {

/// The default limit: 4 GiB (spec/cli.md#memory, "Default").
inline constexpr std::uint64_t default_limit = std::uint64_t{4} << 30;
/// The smallest limit --max-memory accepts: 1 MiB.
inline constexpr std::uint64_t min_limit = std::uint64_t{1} << 20;

/// A --max-memory value: a decimal integer of bytes, optionally followed by one suffix K, M, G
/// or T (binary: 2^10, 2^20, 2^30, 2^40; `KiB`, `MiB`, `GiB`, `TiB` and a trailing `B` are
/// accepted too; case-insensitive), in [1 MiB, 2^62]. Spec: spec/cli.md#memory.
/// UsageError naming `option` and the text otherwise.
[[nodiscard]] std::uint64_t parse_size(std::string_view text, std::string_view option = "--max-memory");

/// `bytes` for a message: exact bytes and the binary size rounded to one decimal
/// (`"5368709120 bytes (5.0 GiB)"`). Spec: spec/cli.md#memory.
[[nodiscard]] std::string show_bytes(std::uint64_t bytes);

/// `count * bytes_each` saturated at UINT64_MAX (estimates never wrap around).
[[nodiscard]] std::uint64_t times(std::uint64_t count, std::uint64_t bytes_each) noexcept;
/// `a + b` saturated at UINT64_MAX.
[[nodiscard]] std::uint64_t plus(std::uint64_t a, std::uint64_t b) noexcept;

/// Throws UsageError "WHAT needs an estimated N bytes (X GiB), more than the memory limit of L
/// bytes (Y GiB); raise it with --max-memory SIZE or make the input smaller (spec/cli.md#memory)"
/// when `estimate > limit`; does nothing otherwise. Spec: spec/cli.md#memory.
void require_within(std::uint64_t estimate, std::uint64_t limit, std::string_view what);

}  // namespace pathref::memory
