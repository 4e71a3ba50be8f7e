#pragma once
/// \file version.hpp
/// What a result must say about the code that produced it (docs/versioning.md): pathref's version,
/// the version of the golden-vector set it was built with (golden/MANIFEST, `golden_set_version`),
/// and the confidence grade of each rule reconstructed from a paper whose equations were lost in
/// extraction (spec/index/*.json, "grade"; cin2021 and sensors2023). All three are read from the
/// source tree when CMake configures and compiled into one generated translation unit
/// (cmake/version.cpp.in), so the binary and the spec index cannot disagree.
#include <optional>
#include <string_view>

namespace pathref {

/// pathref's semantic version, `project(pathref VERSION x.y.z)` in CMakeLists.txt, e.g. "0.2.0".
[[nodiscard]] std::string_view version() noexcept;

/// The golden-vector set's version, `golden_set_version` of golden/MANIFEST: "x.y.z" for a
/// released set, "x.y.z+<8 hex>" while changed vectors are listed under [Unreleased].
[[nodiscard]] std::string_view golden_set_version() noexcept;

/// The confidence grade ('A', 'B' or 'C') of a reconstructed rule as spec/index/*.json states it,
/// or nullopt for a rule whose equation is the paper's own (or an unknown id). A graded rule is a
/// reconstruction: never cite its output as the paper's equation.
[[nodiscard]] std::optional<char> reconstruction_grade(std::string_view rule_id) noexcept;

}  // namespace pathref
