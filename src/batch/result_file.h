// The result file of a sweep on disk: read back what a previous run completed, then append.
//
// A line is complete when its newline is on disk; every line is written with one write() of the
// line and its newline, so a run killed at any moment (SIGKILL, power of the process, a crash)
// leaves complete lines followed by at most one partial line. Reopening for resume reads the
// complete lines and cuts the partial one off.
#pragma once

#include <functional>
#include <string>

#include "linkproof/core/error.h"

namespace linkproof {

/// The result file exists, is not empty, and was not opened to be continued.
class ResultFileExists : public InputError {
 public:
  using InputError::InputError;
};

class ResultFile {
 public:
  /// Called for each complete line of an existing file, with its 1-based number.
  using LineVisitor = std::function<void(const std::string& line, long number)>;

  /// Opens `path` for appending. With `resume`, an existing file's complete lines go to `visit`
  /// first and a trailing partial line is removed; without it, an existing non-empty file is a
  /// ResultFileExists (nothing is overwritten). A missing file is created either way. A path that
  /// exists and is not a regular file (/dev/null, a directory, a FIFO) is an InputError: a result
  /// file is read back and appended to. Errors name the quantity, field "result file", and no
  /// command-line option: the command names the option that gave the path, and says what the
  /// user can do about it.
  ResultFile(const std::string& path, bool resume, const LineVisitor& visit);
  ~ResultFile();
  ResultFile(const ResultFile&) = delete;
  ResultFile& operator=(const ResultFile&) = delete;

  /// Appends `line` and a newline (retrying after EINTR and short writes); InputError on failure.
  void append(const std::string& line);
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  int fd_ = -1;
};

}  // namespace linkproof
