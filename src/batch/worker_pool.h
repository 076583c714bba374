// Worker processes for a sweep (GiNaC is not thread-safe, so parallelism is by process).
//
// fork()s `jobs` workers; worker w computes the cases at positions w, w + jobs, w + 2 jobs, ...
// of `cases` (interleaved, so that the cost growing with n is shared evenly) and writes one line
// per case to its own pipe. The parent reads the lines back in the order of `cases`, whatever
// order the workers finish in. A worker never touches the result file: if it dies, the parent
// has lost nothing it already wrote. Workers ignore SIGINT (the terminal sends it to the whole
// process group; the parent decides) and die with the parent (PR_SET_PDEATHSIG).
#pragma once

#include <sys/types.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace linkproof {

class WorkerPool {
 public:
  /// Computes case k in a worker and returns its line (no newline). Runs after fork(), in the
  /// child; must not write to the parent's files. An exception ends the run with its message;
  /// std::bad_alloc is reported as such (Next::out_of_memory), without allocating.
  using Work = std::function<std::string(long k)>;

  WorkerPool(int jobs, std::vector<long> cases, Work work);
  /// Stops and reaps every worker still running.
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  /// The outcome of waiting for the next line.
  struct Next {
    std::optional<std::string> line;  ///< the next case's line, in the order of `cases`
    int signal = 0;                   ///< SIGINT/SIGTERM received by this process while waiting
    std::string failure;              ///< a worker died or failed: what happened
    /// The worker's failure was std::bad_alloc (an allocation past the memory limit the
    /// workers inherit): the caller rethrows it, as the same failure in one process would.
    bool out_of_memory = false;
  };
  Next next();

  /// Process ids of the workers (for tests that kill one).
  const std::vector<pid_t>& pids() const { return pids_; }

 private:
  std::string describe_end(size_t w);
  std::vector<long> cases_;
  std::vector<pid_t> pids_;
  std::vector<int> fds_;
  std::vector<std::string> buffers_;
  std::vector<bool> reaped_;
  size_t position_ = 0;
};

/// The number of online processors (at least 1): the default of `--jobs`.
int default_jobs();

}  // namespace linkproof
