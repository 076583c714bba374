// Errors: the three channels of linkproof (see STYLE.md).
//   1. Bugs: LINKPROOF_ASSERT (on in every build unless LINKPROOF_ASSERTS is switched off).
//   2. Bad input at a boundary: exceptions derived from linkproof::Error, naming where
//      (file, field) and what is wrong.
//   3. Verification outcomes are values (see verdict.h), never exceptions; an undefined
//      geometric quantity is thrown as UndefinedQuantity inside an evaluation and turned into
//      the verdict `undefined` by whoever runs the claim.
#pragma once

#include <stdexcept>
#include <string>

namespace linkproof {

/// Base of every error linkproof throws on purpose.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Bad input: a file, a field and the problem. CLI exit code 2.
class InputError : public Error {
 public:
  /// `source` is the file (or "<api>"), `field` a path such as "polygon.joints[2][0]".
  InputError(std::string source, std::string field, std::string problem);
  const std::string& source() const { return source_; }
  const std::string& field() const { return field_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string source_, field_, problem_;
};

/// A geometric quantity that does not exist at this configuration (a point at infinity,
/// an angle between a null ray and another, a zero denominator). `quantity` uses the paper's
/// names (e.g. "Q_2", "beta_1", "D = r_{n-2} x r_{n-1}"); `reason` says why.
class UndefinedQuantity : public Error {
 public:
  UndefinedQuantity(std::string quantity, std::string reason);
  const std::string& quantity() const { return quantity_; }
  const std::string& reason() const { return reason_; }

 private:
  std::string quantity_, reason_;
};

/// A broken invariant: a bug in linkproof. CLI exit code 3.
class InternalError : public Error {
 public:
  using Error::Error;
};

[[noreturn]] void assertion_failed(const char* expr, const char* file, int line, const std::string& msg);

}  // namespace linkproof

#if defined(LINKPROOF_NO_ASSERTS)
#define LINKPROOF_ASSERT(cond, msg) ((void)0)
#else
/// Checks an internal invariant; a failure throws InternalError with the location.
#define LINKPROOF_ASSERT(cond, msg) \
  ((cond) ? (void)0 : ::linkproof::assertion_failed(#cond, __FILE__, __LINE__, (msg)))
#endif
