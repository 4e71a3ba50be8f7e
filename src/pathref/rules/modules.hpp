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
void register_han_rules(Registry& r);
void register_han_sim_rules(Registry& r);
void register_ga_planner_rules(Registry& r);
void register_aco_planner_rules(Registry& r);
void register_cin2021_rules(Registry& r);
void register_cin2021_ml_rules(Registry& r);
void register_stats_rules(Registry& r);
void register_sensors2023_dwa_rules(Registry& r);
void register_curves_rules(Registry& r);
void register_sensors2023_rules(Registry& r);
void register_all_modules(Registry& r);

/// Modules of libraries layered on pathref that the core library cannot call (the inflation.*
/// rules of pathref_geometry need CGAL, which libpathref does not link): such a library hands its
/// registration function to add_extension_module (e.g. geometry::install_inflation_rules(), called
/// by the CLI's main and the test program), and register_all_modules calls the extensions after
/// the built-in modules. Adding the same function twice is a no-op. Pre: called before the first
/// registry() -- the registry is immutable once built (UsageError otherwise).
using ModuleRegistration = void (*)(Registry&);
void add_extension_module(ModuleRegistration fn);
}  // namespace pathref::rules
