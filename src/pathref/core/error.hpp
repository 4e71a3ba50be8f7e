#pragma once
/// \file error.hpp
/// The library's error types. Every failure a user can cause is one of these, never a crash.
/// Spec: spec/README.md#errors
#include <cstddef>
#include <stdexcept>
#include <string>

namespace pathref {

/// Base of every pathref error. `kind()` is the stable name used in golden vectors
/// (`"expected": {"error": "<kind>"}`) and in the CLI's messages.
class Error : public std::runtime_error {
 public:
  Error(std::string kind, const std::string& message)
      : std::runtime_error(message), kind_(std::move(kind)) {}
  [[nodiscard]] const std::string& kind() const noexcept { return kind_; }

 private:
  std::string kind_;
};

/// A precondition of a pure function was violated (argument outside the rule's domain).
class DomainError : public Error {
 public:
  explicit DomainError(const std::string& message) : Error("DomainError", message) {}
};

/// Malformed input text. Carries the file, 1-based line and column, and what was expected.
class ParseError : public Error {
 public:
  ParseError(std::string file, std::size_t line, std::size_t column, const std::string& what)
      : Error("ParseError", file + ":" + std::to_string(line) + ":" + std::to_string(column) +
                                ": " + what),
        file_(std::move(file)), line_(line), column_(column) {}
  /// Malformed input that came from no text with lines (a JSON value built by a caller, a rule's
  /// input): `FILE: WHAT`, where WHAT starts with the JSON pointer of the value; line() and
  /// column() are 0.
  ParseError(std::string file, const std::string& what)
      : Error("ParseError", file + ": " + what), file_(std::move(file)), line_(0), column_(0) {}
  [[nodiscard]] const std::string& file() const noexcept { return file_; }
  [[nodiscard]] std::size_t line() const noexcept { return line_; }
  [[nodiscard]] std::size_t column() const noexcept { return column_; }

 private:
  std::string file_;
  std::size_t line_;
  std::size_t column_;
};

/// A request that cannot be served as asked (unknown rule, unknown option name, bad argument).
class UsageError : public Error {
 public:
  explicit UsageError(const std::string& message) : Error("UsageError", message) {}
};

/// A run stopped at an iteration boundary because its caller asked (planners::Request::interrupted;
/// the Python module's Ctrl-C). Not a failure of the input.
class Interrupted : public Error {
 public:
  explicit Interrupted(const std::string& message) : Error("Interrupted", message) {}
};

/// Throws DomainError(message) when `condition` is false. Preconditions are always checked:
/// a reference implementation must never compute on inputs outside a rule's domain.
inline void require(bool condition, const char* message) {
  if (!condition) throw DomainError(message);
}
inline void require(bool condition, const std::string& message) {
  if (!condition) throw DomainError(message);
}

}  // namespace pathref
