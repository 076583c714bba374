// The progress line of a long sweep on stderr, when stderr is a terminal:
//   "  412/1000 cases  41% |########            |  37.5 cases/s  ETA 0:00:15  failures 0"
// redrawn in place (carriage return) at most five times a second. The rate and the ETA count
// only the cases of this run (not those read back by --resume).
#pragma once

#include <chrono>
#include <ostream>
#include <string>

namespace linkproof {

class ProgressBar {
 public:
  /// `out` null: silent. `total` cases in all, `done_before` of them already done (resume).
  ProgressBar(std::ostream* out, long total, long done_before);
  /// `done` cases done in all, `failures` of them with an unexpected outcome.
  void update(long done, long failures);
  /// Draws the last state and ends the line.
  void finish(long done, long failures);

  /// The line for a state (no carriage return): what update() draws. For tests.
  static std::string render(long done, long total, double rate, long failures);

 private:
  std::ostream* out_;
  long total_, done_before_;
  std::chrono::steady_clock::time_point start_, last_draw_;
  bool drawn_ = false;
  void draw(long done, long failures);
};

}  // namespace linkproof
