#include "batch/result_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "linkproof/core/error.h"

namespace linkproof {

namespace {
// What the errors are about: the quantity, named as such (the command line names its option).
const char* const kField = "result file";
}  // namespace

ResultFile::ResultFile(const std::string& path, bool resume, const LineVisitor& visit) : path_(path) {
  std::error_code ec;
  const bool exists = std::filesystem::exists(path, ec);
  if (exists && !std::filesystem::is_regular_file(path, ec))
    throw InputError(path, kField, "is not a regular file (a result file is appended to and read back)");
  if (exists && !resume && std::filesystem::file_size(path, ec) > 0)
    throw ResultFileExists(path, kField, "exists and is not empty (a result file is never overwritten)");
  if (exists && resume) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, kField, "cannot be read");
    std::string line;
    long complete_bytes = 0, number = 0;
    while (std::getline(in, line)) {
      if (in.eof()) break;  // no newline: a line cut off by a crash
      complete_bytes += static_cast<long>(line.size()) + 1;
      visit(line, ++number);
    }
    const long size = static_cast<long>(std::filesystem::file_size(path, ec));
    // Only a line after lines the visitor accepted is taken for one a crash cut off: a file
    // without any complete line may be anything (a mistyped --out), and is never cut.
    if (size > complete_bytes && number == 0)
      throw InputError(path, kField,
                       "has no complete line, so it is not a result file of this run and is left as it is (a run "
                       "killed while writing its first line leaves such a file: remove it to start again)");
    if (size > complete_bytes) {
      std::filesystem::resize_file(path, static_cast<std::uintmax_t>(complete_bytes), ec);
      if (ec) throw InputError(path, kField, "cannot cut off the incomplete last line: " + ec.message());
    }
  }
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd_ < 0) throw InputError(path, kField, std::string("cannot be opened for writing: ") + std::strerror(errno));
}

ResultFile::~ResultFile() {
  if (fd_ >= 0) ::close(fd_);
}

void ResultFile::append(const std::string& line) {
  const std::string data = line + "\n";
  size_t done = 0;
  while (done < data.size()) {
    const ssize_t w = ::write(fd_, data.data() + done, data.size() - done);
    if (w < 0 && errno == EINTR) continue;
    if (w < 0) throw InputError(path_, kField, std::string("write failed: ") + std::strerror(errno));
    done += static_cast<size_t>(w);
  }
}

}  // namespace linkproof
