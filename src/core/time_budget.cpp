#include "core/time_budget.h"

#include <atomic>
#include <chrono>
#include <cstdint>

#include <fmt/format.h>

namespace linkproof {

namespace {
using Clock = std::chrono::steady_clock;
// Deadline in clock ticks since the epoch; 0: no budget. Atomic: the watchdog thread reads it.
std::atomic<std::int64_t> deadline_ticks{0};
std::atomic<double> limit{0};
std::atomic<TimeBudget::ProgressReporter> reporter{nullptr};
}  // namespace

BudgetExceeded::BudgetExceeded(std::string phase, double limit_seconds)
    : phase_(std::move(phase)),
      limit_(limit_seconds),
      message_(fmt::format("time budget of {} s exceeded before {}; the run was stopped and nothing is claimed "
                           "about what it had not finished",
                           limit_seconds, phase_)) {}

void TimeBudget::start(double seconds) {
  const auto ticks = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
  limit.store(seconds);
  deadline_ticks.store((Clock::now() + ticks).time_since_epoch().count());
}

void TimeBudget::clear() {
  deadline_ticks.store(0);
  limit.store(0);
}

double TimeBudget::limit_seconds() { return limit.load(); }

bool TimeBudget::expired() {
  const std::int64_t d = deadline_ticks.load(std::memory_order_relaxed);
  return d != 0 && Clock::now().time_since_epoch().count() >= d;
}

void TimeBudget::check(std::string_view phase) {
  if (expired()) throw BudgetExceeded(std::string(phase), limit.load());
  if (const ProgressReporter r = reporter.load(std::memory_order_relaxed)) r(phase);
}

void TimeBudget::set_progress_reporter(ProgressReporter r) { reporter.store(r); }

}  // namespace linkproof
