// Exact decimal numbers (spec/formats.md, "Polygon scene (JSON)", numbers).
#include "pathref/geometry/decimal.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <system_error>

namespace pathref::geometry {

namespace {
bool is_digit(char c) noexcept { return c >= '0' && c <= '9'; }
}  // namespace

std::optional<Decimal> parse_decimal(std::string_view t) {
  std::size_t i = 0;
  const bool neg = i < t.size() && t[i] == '-';
  if (neg) ++i;
  // integer part: 0 | [1-9][0-9]*
  if (i >= t.size() || !is_digit(t[i])) return std::nullopt;
  std::string digits;
  if (t[i] == '0') {
    ++i;
    if (i < t.size() && is_digit(t[i])) return std::nullopt;
  } else {
    while (i < t.size() && is_digit(t[i])) digits.push_back(t[i++]);
  }
  std::int64_t frac_len = 0;
  if (i < t.size() && t[i] == '.') {
    ++i;
    if (i >= t.size() || !is_digit(t[i])) return std::nullopt;
    while (i < t.size() && is_digit(t[i])) {
      digits.push_back(t[i++]);
      ++frac_len;
      if (frac_len > 100000) return std::nullopt;
    }
  }
  std::int64_t exp = 0;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    bool eneg = false;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) eneg = t[i++] == '-';
    if (i >= t.size() || !is_digit(t[i])) return std::nullopt;
    while (i < t.size() && is_digit(t[i])) {
      exp = exp * 10 + (t[i++] - '0');
      if (exp > 1000000) return std::nullopt;  // far outside the limits either way
    }
    if (eneg) exp = -exp;
  }
  if (i != t.size()) return std::nullopt;
  // normalise: strip leading zeros, then trailing zeros into the exponent
  std::size_t lead = 0;
  while (lead < digits.size() && digits[lead] == '0') ++lead;
  digits.erase(0, lead);
  if (digits.empty()) return Decimal{};
  std::int64_t e = exp - frac_len;
  while (digits.back() == '0') {
    digits.pop_back();
    ++e;
  }
  if (digits.size() > max_decimal_digits) return std::nullopt;
  if (e < -max_decimal_exponent || e > max_decimal_exponent) return std::nullopt;
  return Decimal{neg, std::move(digits), static_cast<std::int32_t>(e)};
}

Decimal decimal_from_integer(std::int64_t v) {
  const std::string s = std::to_string(v);
  auto d = parse_decimal(s);
  return *d;  // at most 19 digits, exponent <= 18: always within the limits
}

Fraction to_fraction(const Decimal& d) {
  std::string num = (d.negative ? "-" : "") + d.digits;
  std::string den = "1";
  if (d.exp10 >= 0)
    num.append(static_cast<std::size_t>(d.exp10), '0');
  else
    den.append(static_cast<std::size_t>(-d.exp10), '0');
  return {num, den};
}

std::string to_string(const Decimal& d) {
  std::string s = d.negative ? "-" : "";
  if (d.exp10 >= 0) {
    s += d.digits;
    s.append(static_cast<std::size_t>(d.exp10), '0');
    return s;
  }
  const auto frac = static_cast<std::size_t>(-d.exp10);
  if (d.digits.size() > frac) {
    s += d.digits.substr(0, d.digits.size() - frac);
    s += '.';
    s += d.digits.substr(d.digits.size() - frac);
  } else {
    s += "0.";
    s.append(frac - d.digits.size(), '0');
    s += d.digits;
  }
  return s;
}

std::optional<Decimal> decimal_from_double_shortest(double v) {
  if (!std::isfinite(v)) return std::nullopt;
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  if (r.ec != std::errc{}) return std::nullopt;
  std::string text(buf, r.ptr);
  // to_chars writes "1e+20" and "-0": JSON-number compatible except for the '+' in the exponent
  // (accepted by the grammar above) and "-0" (parses as zero).
  return parse_decimal(text);
}

}  // namespace pathref::geometry
