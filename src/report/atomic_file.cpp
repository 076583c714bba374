#include "report/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "linkproof/core/error.h"

namespace linkproof {

namespace fs = std::filesystem;

void write_files_atomically(const std::vector<OutputFile>& files, const std::string& option) {
  std::vector<fs::path> temps, renamed;
  const auto fail = [&](const fs::path& path, const std::string& problem) {
    std::error_code ignored;
    for (const auto& t : temps) fs::remove(t, ignored);
    for (const auto& r : renamed) fs::remove(r, ignored);
    throw InputError("<command line>", option, "cannot write '" + path.string() + "': " + problem);
  };
  for (const auto& f : files) {
    std::error_code ec;
    if (fs::is_directory(fs::symlink_status(f.path, ec))) fail(f.path, "a directory of that name is in the way");
  }
  for (size_t k = 0; k < files.size(); ++k) {
    const fs::path& path = files[k].path;
    // The temporary's name does not grow with the final one: a name near the 255-byte limit
    // still gets a temporary file.
    temps.push_back(path.parent_path() / (".linkproof-tmp-" + std::to_string(::getpid()) + "-" + std::to_string(k)));
    std::ofstream out(temps.back(), std::ios::binary | std::ios::trunc);
    if (!out) fail(path, std::strerror(errno));
    out.write(files[k].text.data(), static_cast<std::streamsize>(files[k].text.size()));
    out.close();  // flushes: a full disk shows here
    if (!out) fail(path, "write failed (disk full?)");
  }
  for (size_t k = 0; k < files.size(); ++k) {
    std::error_code ec;
    fs::rename(temps[k], files[k].path, ec);
    if (ec) fail(files[k].path, ec.message());
    renamed.push_back(files[k].path);
  }
}

void write_file_atomically(const fs::path& path, const std::string& text, const std::string& option) {
  write_files_atomically({{path, text}}, option);
}

}  // namespace linkproof
