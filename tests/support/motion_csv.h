// Recorded-motion CSV text for check-data tests.
#pragma once

#include <sstream>
#include <string>
#include <vector>

namespace linkproof::test {

/// The header and the first data row of `csv` with every `<joint>.x` negated: the recording
/// mirrored in the y axis (every distance kept, every triangle's orientation reversed).
inline std::string mirrored_first_row(const std::string& csv) {
  std::istringstream in(csv);
  std::string line, out;
  std::vector<std::string> header;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream ls(line);
    for (std::string c; std::getline(ls, c, ',');) cells.push_back(c);
    if (header.empty()) {
      header = cells;
      out += line + "\n";
      continue;
    }
    for (size_t k = 0; k < cells.size(); ++k)
      if (header[k].size() > 2 && header[k].compare(header[k].size() - 2, 2, ".x") == 0)
        cells[k] = cells[k][0] == '-' ? cells[k].substr(1) : "-" + cells[k];
    for (size_t k = 0; k < cells.size(); ++k) out += (k ? "," : "") + cells[k];
    return out + "\n";
  }
  return out;
}

}  // namespace linkproof::test
