// `pathref plan` and `pathref maps` (filled in by the planning/CLI work).
#include "commands.hpp"

namespace pathref::cli {
void add_plan_commands(CLI::App& /*app*/, Action& /*run*/) {}
}  // namespace pathref::cli
