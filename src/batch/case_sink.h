// Where finished cases go, in case order: the tally (the report), the result file, and the
// scene directory. Shared by a running sweep, a resumed one, `merge` and the MPI driver, so that
// all of them write a case the same way.
#pragma once

#include <optional>
#include <string>

#include "batch/result_file.h"
#include "check/sweep_tally.h"
#include "report/sweep_lines.h"

namespace linkproof {

class CaseSink {
 public:
  /// `file` may be null (no result file); `scenes_dir` empty: no scenes.
  CaseSink(const std::vector<Claim>& catalogue, const SweepOptions& options, ResultFile* file,
           std::string scenes_dir);

  /// Counts case c; writes its line to the result file when `write` (not for lines read back
  /// from it) and its scene when it has an unexpected outcome. `origin` names where c came from
  /// for errors (file and line): c must carry the evidence the report keeps from it.
  void add(SweepCase& c, bool write, const std::string& origin_file, const std::string& origin_field);

  /// From now on, write added cases to `file` (null: nowhere).
  void set_file(ResultFile* file) { file_ = file; }

  const SweepTally& tally() const { return tally_; }
  const SweepOptions& options() const { return options_; }

 private:
  SweepOptions options_;
  SweepTally tally_;
  ResultFile* file_;
  std::string scenes_dir_;
};

/// Checks that `line` (a case line of `file`, at `where`) is case `expected` of sweep `o`: same
/// case number, seed, n, index and arithmetic (InputError naming both cases otherwise), and that
/// it holds what a run of `catalogue` gives at its n: a verdict of every claim that applies at n
/// and of no other, and the others listed as not applicable in catalogue order (InputError
/// naming the claim otherwise). With the line's digest (report/sweep_lines.h), this is how a
/// line read back (--resume, merge) is trusted.
void check_case_identity(const SweepLine& line, long expected, const SweepOptions& o,
                         const std::vector<Claim>& catalogue, const std::string& file, const std::string& where);

}  // namespace linkproof
