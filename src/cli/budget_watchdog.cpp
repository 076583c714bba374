#include "budget_watchdog.h"

#include <fmt/format.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <thread>

#include <cln/malloc.h>

#include "cli.h"
#include "command.h"
#include "core/time_budget.h"

#if defined(__SANITIZE_ADDRESS__)
#define LINKPROOF_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define LINKPROOF_UNDER_ASAN 1
#endif
#endif

namespace linkproof::cli {

namespace {

// Each scope arms the watchdog with a new generation; a watchdog fires only if its generation
// is still the armed one when it wakes (a finished run disarms it).
std::atomic<unsigned> armed_generation{0};

void write_all(int fd, const std::string& s) {
  size_t done = 0;
  while (done < s.size()) {
    const ssize_t w = ::write(fd, s.data() + done, s.size() - done);
    if (w <= 0) return;
    done += static_cast<size_t>(w);
  }
}

void start_watchdog(unsigned generation, double after_seconds, std::string text, std::string json) {
  std::thread([=] {
    const auto wake = std::chrono::steady_clock::now() + std::chrono::duration<double>(after_seconds);
    while (std::chrono::steady_clock::now() < wake) {
      if (armed_generation.load() != generation) return;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    if (armed_generation.load() != generation) return;
    write_all(STDERR_FILENO, text);
    write_all(STDOUT_FILENO, json);
    ::_exit(kBadInput);
  }).detach();
}

// CLN's allocations throw std::bad_alloc like operator new, so a run past the memory limit is
// reported the same way whichever library allocated.
void* throwing_malloc(size_t size) {
  if (void* p = std::malloc(size)) return p;
  throw std::bad_alloc();
}

// The address-space limit before the run set its own, restored to report an allocation failure.
std::optional<rlimit> limit_before;

void limit_memory(int max_memory_mb) {
#if !defined(LINKPROOF_UNDER_ASAN)
  if (max_memory_mb <= 0) return;
  const rlim_t bytes = static_cast<rlim_t>(max_memory_mb) << 20;
  rlimit current{};
  if (getrlimit(RLIMIT_AS, &current) != 0) return;
  if (current.rlim_cur != RLIM_INFINITY && current.rlim_cur <= bytes) return;  // already tighter
  const rlimit wanted{bytes, current.rlim_max};
  if (setrlimit(RLIMIT_AS, &wanted) == 0) limit_before = current;
#else
  (void)max_memory_mb;
#endif
}

// The phase line on a terminal: "linkproof: the per-n proof of ... at n = 9 (12 s)", rewritten in
// place at most 4 times a second, erased when the run ends.
std::chrono::steady_clock::time_point run_start, last_progress;
bool progress_shown = false;

void show_progress(std::string_view phase) {
  const auto now = std::chrono::steady_clock::now();
  if (now - last_progress < std::chrono::milliseconds(250) || now - run_start < std::chrono::seconds(1)) return;
  last_progress = now;
  const double seconds = std::chrono::duration<double>(now - run_start).count();
  std::string line = fmt::format("\rlinkproof: {} ({:.0f} s)", phase, seconds);
  if (line.size() > 100) line.resize(100);
  line += "\x1b[K";  // erase the rest of the line
  write_all(STDERR_FILENO, line);
  progress_shown = true;
}

}  // namespace

double watchdog_grace_seconds(double max_seconds) { return std::clamp(0.05 * max_seconds, 1.0, 30.0); }

BudgetScope::BudgetScope(const Resources& resources, bool program, bool json) {
  const unsigned generation = armed_generation.fetch_add(1) + 1;
  if (resources.max_seconds > 0) {
    TimeBudget::start(resources.max_seconds);
    if (program) {
      const double grace = watchdog_grace_seconds(resources.max_seconds);
      const ErrorReport report = command_line_error_report(
          "--max-seconds", fmt::format("time budget of {} s exceeded: a step did not finish within {} s of it, and the "
                                       "run was stopped; nothing after the last printed result was checked",
                                       resources.max_seconds, grace));
      std::ostringstream out, err;
      print_error(out, err, report, json);
      start_watchdog(generation, resources.max_seconds + grace, err.str(), out.str());
    }
  }
  if (program) {
    cln::malloc_hook = throwing_malloc;
    limit_memory(resources.max_memory_mb);
    if (::isatty(STDERR_FILENO)) {
      run_start = last_progress = std::chrono::steady_clock::now();
      TimeBudget::set_progress_reporter(show_progress);
    }
  }
}

BudgetScope::~BudgetScope() {
  TimeBudget::set_progress_reporter(nullptr);
  if (progress_shown) write_all(STDERR_FILENO, "\r\x1b[K");
  progress_shown = false;
  lift_memory_limit();
  armed_generation.fetch_add(1);
  TimeBudget::clear();
}

void lift_memory_limit() {
  if (limit_before) setrlimit(RLIMIT_AS, &*limit_before);
  limit_before.reset();
}

ErrorReport memory_error_report(const Resources& resources) {
  return command_line_error_report(
      "--max-memory-mb",
      resources.max_memory_mb > 0
          ? fmt::format("memory budget of {} MiB exceeded (raise --max-memory-mb, or ask for less work)",
                        resources.max_memory_mb)
          : std::string("out of memory"));
}

}  // namespace linkproof::cli
