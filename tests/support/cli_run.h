// Runs the command line in-process for tests: exit code and both output streams.
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "cli.h"

namespace linkproof::test {

struct CliRun {
  int code;
  std::string out, err;
};

inline CliRun run_cli(std::vector<std::string> args) {
  std::ostringstream out, err;
  const int code = cli::run(args, out, err);
  return {code, out.str(), err.str()};
}

}  // namespace linkproof::test
