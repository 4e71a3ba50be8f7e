#pragma once
/// \file paths.hpp
/// Where the tests find the repository and ../shared. Only tests/support/paths.cpp is compiled
/// with the absolute paths, so every other test translation unit is the same in every checkout
/// (a compiler cache shared between checkouts then hits).
#include <string>

namespace pathref::testing {
/// The repository root (absolute path, no trailing slash).
[[nodiscard]] std::string source_dir();
/// The ../shared folder beside the repository (may not exist; tests that need it skip).
[[nodiscard]] std::string shared_dir();
}  // namespace pathref::testing
