#pragma once
/// \file modules.hpp
/// One registration function per module (kept explicit: static-initialiser registration is
/// dropped by the linker from static libraries). Add a line here and in modules.cpp per module.
#include "pathref/rules/registry.hpp"

namespace pathref::rules {
void register_rng_rules(Registry& r);
void register_grid_rules(Registry& r);
void register_metrics_rules(Registry& r);
void register_search_rules(Registry& r);
void register_mecanum_rules(Registry& r);
void register_shi2022_rules(Registry& r);
void register_all_modules(Registry& r);
}  // namespace pathref::rules
