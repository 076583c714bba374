// A wall-clock budget for one run (the CLI's --max-seconds; docs/limits.md).
//
// Long phases call TimeBudget::check(phase) at the start of each unit of work (a coefficient of
// a proof, a counterexample attempt, a claim of a check, a rank of a count, a sweep case). Once
// the budget has run out, check throws BudgetExceeded naming the phase, and the run ends with an
// error that names it (never a pass, never a partial report). A unit that never reaches a check
// point (one GiNaC normal() of a huge expression) is stopped by the program's watchdog
// (src/cli/budget_watchdog.h), not here.
#pragma once

#include <string>
#include <string_view>

namespace linkproof {

/// The budget ran out before `phase` could start. Deliberately not a std::exception: the
/// handlers that turn an evaluation's failure into an `error` verdict and go on must not catch
/// it, so it ends the whole run (the CLI reports it as exit 2 naming --max-seconds).
class BudgetExceeded {
 public:
  BudgetExceeded(std::string phase, double limit_seconds);
  const std::string& phase() const { return phase_; }
  double limit_seconds() const { return limit_; }
  /// "time budget of S s (--max-seconds) exceeded before PHASE; ..."
  const char* what() const noexcept { return message_.c_str(); }

 private:
  std::string phase_;
  double limit_;
  std::string message_;
};

/// Process-wide: one budget per run (the CLI starts it after parsing; library users may too).
class TimeBudget {
 public:
  /// Starts a budget of `seconds` from now (> 0), replacing any earlier one.
  static void start(double seconds);
  /// No budget from now on.
  static void clear();
  /// The limit of the running budget in seconds, 0 when there is none.
  static double limit_seconds();
  /// True when a budget is running and has run out.
  static bool expired();
  /// Throws BudgetExceeded(phase) when the budget has run out; otherwise costs one clock read
  /// (and a call of the progress reporter, when one is set).
  static void check(std::string_view phase);
  /// Called by check with the phase about to start (the CLI shows it on a terminal); null: none.
  using ProgressReporter = void (*)(std::string_view phase);
  static void set_progress_reporter(ProgressReporter reporter);
};

}  // namespace linkproof
