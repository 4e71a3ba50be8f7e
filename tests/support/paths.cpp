#include "support/paths.hpp"

#include <cstdlib>
#include <iostream>

namespace pathref::testing {
std::string source_dir() { return PATHREF_SOURCE_DIR; }
std::string shared_dir() { return PATHREF_SHARED_DIR; }

void skip_test(const std::string& why) {
  std::cout << "SKIPPED: " << why << std::endl;
  const char* ctest = std::getenv("PATHREF_CTEST_SKIP");
  if (ctest != nullptr && std::string(ctest) == "1") std::_Exit(77);
}
}  // namespace pathref::testing
