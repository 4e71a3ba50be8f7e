#include "support/paths.hpp"

namespace pathref::testing {
std::string source_dir() { return PATHREF_SOURCE_DIR; }
std::string shared_dir() { return PATHREF_SHARED_DIR; }
}  // namespace pathref::testing
