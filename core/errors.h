// Typed exceptions thrown by the library. Apps map each class to one exit code
// (see docs/errors.md); messages are one line and name the problem and where.
#pragma once

#include <stdexcept>
#include <string>

namespace unfold {

/// Base of every error the library throws on purpose.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
  /// Process exit code for this class of error.
  virtual int exit_code() const { return 1; }
};

/// Bad parameters or configuration (unknown key, out-of-range value, bad flag).
class UsageError : public Error {
 public:
  using Error::Error;
  int exit_code() const override { return 2; }
};

/// The input mesh (or another input file) is missing, unreadable or unusable.
class InputError : public Error {
 public:
  using Error::Error;
  int exit_code() const override { return 3; }
};

/// The computation failed: a factorization broke down, NaN appeared, TetGen gave up.
class NumericalError : public Error {
 public:
  using Error::Error;
  int exit_code() const override { return 4; }
};

/// An output file could not be written.
class OutputError : public Error {
 public:
  using Error::Error;
  int exit_code() const override { return 5; }
};

}  // namespace unfold
