// SIGINT and SIGTERM during a batch run: instead of dying mid-case, the run notes the signal,
// finishes the line it is writing, stops its workers and returns, leaving a result file that
// `--resume` continues. Handlers are installed without SA_RESTART, so a blocking read returns
// (EINTR) and the run can look at the flag.
#pragma once

namespace linkproof {

/// Installs the handlers for its lifetime and restores the previous ones after. Not nested.
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
};

/// The signal received since the guard was installed (SIGINT or SIGTERM), or 0.
int interrupt_signal();

}  // namespace linkproof
