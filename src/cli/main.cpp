#include <iostream>

#include "cli.h"
#include "core/large_blocks.h"

int main(int argc, char** argv) {
  linkproof::keep_large_blocks_for_reuse();  // a process setting of the executable (core/large_blocks.h)
  std::vector<std::string> args(argv + 1, argv + argc);
  return linkproof::cli::run(args, std::cout, std::cerr, linkproof::cli::RunMode::Program);
}
