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

/// A test that cannot run here (../shared absent) must show as SKIPPED, never as passed
/// (issue 17, "silent passes"). Under ctest (PATHREF_CTEST_SKIP=1, set by tests/CMakeLists.txt)
/// this prints `why` and ends the process with 77, ctest's SKIP_RETURN_CODE for every test of
/// pathref_tests: each test case runs in its own process there. Run directly, the test binary
/// goes on with the other test cases; the caller returns, and Catch2 counts the case as passed
/// with the printed reason beside it.
void skip_test(const std::string& why);
}  // namespace pathref::testing
