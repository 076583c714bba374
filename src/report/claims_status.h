// What the program decided about a list of claims, handed to the reports that print it: the exit
// status and, per claim, whether it is as expected under the policy the program applied (with
// --strict or without). Reports print these decisions and never make them: exit codes and the
// --strict policy live in cli/ (cli/exit_status.h) and nowhere else.
#pragma once

#include <vector>

namespace linkproof {

struct ClaimsStatus {
  /// The exit code the command ends with (docs/check.md, "Exit status").
  int exit_status = 0;
  /// The policy applied was --strict's: the reports print its marks ("NOT AS EXPECTED
  /// (strict)", the summary's "strict": true, "(strict: ... counts)").
  bool strict = false;
  /// Per claim, in the order of the result's claims: as expected under that policy.
  std::vector<bool> as_expected;
};

}  // namespace linkproof
