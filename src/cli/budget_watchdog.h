// The resource budgets of one run: --max-seconds and --max-memory-mb (docs/limits.md).
//
// Time: TimeBudget (core/time_budget.h) is started for the run; long phases check it at each unit
// of work and stop with an error that names the phase. In the program (RunMode::Program) a
// watchdog thread also ends the process shortly after the deadline, for a unit of work that never
// reaches a check point (one GiNaC normal() of a huge expression): it prints the same error (one
// JSON object with --json) and exits 2. A sweep's result file keeps every complete case line, so
// `--resume` continues after such a stop.
// Memory: RLIMIT_AS in the program (not under AddressSanitizer, which reserves terabytes of
// address space); an allocation past it throws std::bad_alloc, reported as exit 2.
#pragma once


#include "error_report.h"

namespace linkproof::cli {

inline constexpr double kDefaultMaxSeconds = 3600;
inline constexpr int kDefaultMaxMemoryMb = 8192;

struct Resources {
  double max_seconds = kDefaultMaxSeconds;  ///< 0: no time budget
  int max_memory_mb = kDefaultMaxMemoryMb;  ///< 0: no memory limit
};


/// How long after the deadline the watchdog stops the program: 5 % of the budget, at least 1 s
/// and at most 30 s (the time a unit of work may overrun its check point).
double watchdog_grace_seconds(double max_seconds);

/// Starts the budgets of `resources` for its lifetime (the watchdog and the memory limit only when
/// `program`); the error the watchdog prints is formatted for `json`.
class BudgetScope {
 public:
  BudgetScope(const Resources& resources, bool program, bool json);
  ~BudgetScope();
  BudgetScope(const BudgetScope&) = delete;
  BudgetScope& operator=(const BudgetScope&) = delete;
};

/// Restores the address-space limit the process had before the run (so that the failure can be
/// reported: printing allocates too).
void lift_memory_limit();

/// The report of an allocation that failed under --max-memory-mb (exit 2).
ErrorReport memory_error_report(const Resources& resources);

}  // namespace linkproof::cli
