// libFuzzer target: the command-line parser (src/cli, parse_only: options and validators, no
// work is run). The input is split at newlines into arguments. Any arguments must give an exit
// code, or nothing when the command would run; never a crash or an exception.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "cli.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> args;
  std::string current;
  for (std::size_t i = 0; i < size; ++i) {
    if (data[i] == '\n') {
      args.push_back(current);
      current.clear();
    } else {
      current += static_cast<char>(data[i]);
    }
  }
  if (!current.empty()) args.push_back(current);
  std::ostringstream out, err;
  const auto code = linkproof::cli::parse_only(args, out, err);
  if (code && (*code < 0 || *code > 3)) __builtin_trap();
  return 0;
}
