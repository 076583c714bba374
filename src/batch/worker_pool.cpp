#include "batch/worker_pool.h"

#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <new>
#include <string_view>

#include <fmt/format.h>

#include "batch/interrupt.h"
#include "linkproof/core/error.h"

namespace linkproof {

namespace {

// A worker's last line: "!" then what went wrong; this one for std::bad_alloc.
constexpr char kOutOfMemoryLine[] = "!\x01out of memory\n";

bool write_all(int fd, std::string_view data) {
  size_t done = 0;
  while (done < data.size()) {
    const ssize_t w = ::write(fd, data.data() + done, data.size() - done);
    if (w < 0 && errno == EINTR) continue;
    if (w < 0) return false;
    done += static_cast<size_t>(w);
  }
  return true;
}

[[noreturn]] void run_worker(int fd, size_t w, size_t jobs, const std::vector<long>& cases,
                             const WorkerPool::Work& work, pid_t parent) {
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() != parent) ::_exit(1);  // the parent died before prctl
  std::signal(SIGINT, SIG_IGN);
  std::signal(SIGTERM, SIG_DFL);
  std::signal(SIGPIPE, SIG_DFL);
  try {
    for (size_t i = w; i < cases.size(); i += jobs)
      if (!write_all(fd, work(cases[i]) + "\n")) ::_exit(1);
  } catch (const std::bad_alloc&) {
    // The memory budget is spent: report it without allocating (a string_view of a literal).
    write_all(fd, std::string_view(kOutOfMemoryLine));
    ::_exit(3);
  } catch (const std::exception& e) {
    std::string message = e.what();
    for (char& c : message)
      if (c == '\n') c = ' ';
    write_all(fd, "!" + message + "\n");
    ::_exit(3);
  }
  ::_exit(0);  // no atexit handlers, no flushing of the parent's buffers
}

}  // namespace

int default_jobs() {
  const long n = ::sysconf(_SC_NPROCESSORS_ONLN);
  return n > 0 ? static_cast<int>(n) : 1;
}

WorkerPool::WorkerPool(int jobs, std::vector<long> cases, Work work) : cases_(std::move(cases)) {
  const size_t count = std::max<size_t>(1, std::min<size_t>(static_cast<size_t>(std::max(jobs, 1)), cases_.size()));
  const pid_t parent = ::getpid();
  for (size_t w = 0; w < count; ++w) {
    int p[2];
    if (::pipe(p) != 0) throw InternalError(std::string("pipe: ") + std::strerror(errno));
    const pid_t pid = ::fork();
    if (pid < 0) throw InternalError(std::string("fork: ") + std::strerror(errno));
    if (pid == 0) {
      ::close(p[0]);
      for (int fd : fds_) ::close(fd);  // the other workers' read ends
      run_worker(p[1], w, count, cases_, work, parent);
    }
    ::close(p[1]);
    pids_.push_back(pid);
    fds_.push_back(p[0]);
    buffers_.emplace_back();
    reaped_.push_back(false);
  }
}

WorkerPool::~WorkerPool() {
  for (size_t w = 0; w < pids_.size(); ++w) {
    ::close(fds_[w]);
    if (reaped_[w]) continue;
    ::kill(pids_[w], SIGKILL);  // harmless if it has already exited (a zombie until reaped)
    int status = 0;
    while (::waitpid(pids_[w], &status, 0) < 0 && errno == EINTR) {
    }
  }
}

std::string WorkerPool::describe_end(size_t w) {
  int status = 0;
  while (::waitpid(pids_[w], &status, 0) < 0 && errno == EINTR) {
  }
  reaped_[w] = true;
  if (WIFSIGNALED(status))
    return fmt::format("worker {} (pid {}) was killed by signal {} ({})", w + 1, pids_[w], WTERMSIG(status),
                       strsignal(WTERMSIG(status)));
  return fmt::format("worker {} (pid {}) exited with status {} before its last case", w + 1, pids_[w],
                     WIFEXITED(status) ? WEXITSTATUS(status) : -1);
}

WorkerPool::Next WorkerPool::next() {
  Next out;
  LINKPROOF_ASSERT(position_ < cases_.size(), "no case left to read");
  const size_t w = position_ % pids_.size();
  std::string& buffer = buffers_[w];
  size_t newline;
  while ((newline = buffer.find('\n')) == std::string::npos) {
    if (interrupt_signal() != 0) {
      out.signal = interrupt_signal();
      return out;
    }
    char chunk[65536];
    const ssize_t r = ::read(fds_[w], chunk, sizeof chunk);
    if (r > 0) {
      buffer.append(chunk, static_cast<size_t>(r));
    } else if (r < 0 && errno == EINTR) {
      continue;
    } else {
      out.failure = describe_end(w) + fmt::format(" while computing case {}", cases_[position_]);
      return out;
    }
  }
  std::string line = buffer.substr(0, newline);
  buffer.erase(0, newline + 1);
  if (!line.empty() && line[0] == '!') {
    out.out_of_memory = line + "\n" == kOutOfMemoryLine;
    out.failure = fmt::format("worker {} failed on case {}: {}", w + 1, cases_[position_],
                              out.out_of_memory ? "out of memory (std::bad_alloc)" : line.substr(1));
    return out;
  }
  ++position_;
  out.line = std::move(line);
  return out;
}

}  // namespace linkproof
