#include "linkproof/report/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "linkproof/core/error.h"

namespace linkproof {

void write_file_atomically(const std::filesystem::path& path, const std::string& text, const std::string& option) {
  const std::filesystem::path temp =
      path.parent_path() / ("." + path.filename().string() + ".tmp-" + std::to_string(::getpid()));
  const auto fail = [&](const std::string& problem) {
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    throw InputError("<command line>", option, "cannot write '" + path.string() + "': " + problem);
  };
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) fail(std::strerror(errno));
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();  // flushes: a full disk shows here
    if (!out) fail("write failed (disk full?)");
  }
  std::error_code ec;
  std::filesystem::rename(temp, path, ec);
  if (ec) fail(ec.message());
}

}  // namespace linkproof
