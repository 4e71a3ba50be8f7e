#pragma once
/// \file decimal.hpp
/// Exact decimal numbers as read from scene files: the JSON number text "0.3" means 3/10, never
/// the binary64 nearest to it. A Decimal is m * 10^e with an integer significand m (a string of
/// digits) and an integer exponent e; it converts to an exact rational numerator/denominator.
/// Spec: spec/formats.md#polygon-scene-json (numbers), spec/inflation.md
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace pathref::geometry {

/// value = (negative ? -1 : 1) * digits * 10^exp10, digits without leading zeros ("0" for zero,
/// then negative == false and exp10 == 0) and without trailing zeros (moved into exp10), so equal
/// values have equal representations.
struct Decimal {
  bool negative = false;
  std::string digits = "0";
  std::int32_t exp10 = 0;

  [[nodiscard]] bool is_zero() const noexcept { return digits == "0"; }
  friend bool operator==(const Decimal&, const Decimal&) = default;
};

/// Largest number of significant digits and largest |exp10| of a Decimal (scene limits).
inline constexpr std::size_t max_decimal_digits = 30;
inline constexpr std::int32_t max_decimal_exponent = 30;

/// Parses JSON number text (-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?) exactly.
/// Returns nullopt when the text is not a JSON number, has more than max_decimal_digits
/// significant digits, or its normalised exponent is outside [-max_decimal_exponent,
/// max_decimal_exponent]. Spec: formats.md "Polygon scene (JSON)", numbers.
[[nodiscard]] std::optional<Decimal> parse_decimal(std::string_view text);

/// The Decimal of an integer.
[[nodiscard]] Decimal decimal_from_integer(std::int64_t v);

/// The exact rational value as reduced-or-not numerator and positive denominator, both as
/// decimal digit strings ("-3", "10" for -0.3; "300", "1" for 3e2).
struct Fraction {
  std::string numerator;
  std::string denominator;
};
[[nodiscard]] Fraction to_fraction(const Decimal& d);

/// Canonical decimal text: plain notation ("-0.3", "300", "0.000125"); parse_decimal(to_string(d)) == d.
[[nodiscard]] std::string to_string(const Decimal& d);

/// The Decimal written by the shortest round-trip text of a finite binary64 (std::to_chars),
/// i.e. the decimal a person wrote when the JSON library has already turned it into a double.
/// Exact for every decimal of at most 15 significant digits. nullopt for non-finite values.
[[nodiscard]] std::optional<Decimal> decimal_from_double_shortest(double v);

}  // namespace pathref::geometry
