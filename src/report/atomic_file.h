// Writing output files so that none is ever half-written, and a set of files (a report and its
// figures) appears whole or not at all.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace linkproof {

/// One file of a set written together.
struct OutputFile {
  std::filesystem::path path;
  std::string text;
};

/// Writes every file of `files` or none of them:
///  1. each path is checked first: an existing directory there (which a rename cannot
///     replace) fails before anything is written;
///  2. each text goes to a temporary file in the directory of its path,
///     ".linkproof-tmp-<pid>-<k>" (a short name, whatever the length of the final one), and is
///     flushed and closed: a full disk or a missing directory shows here;
///  3. only when all are written are they renamed onto their paths, in order (atomic on one
///     file system: a reader sees the old file or the new one).
/// On any failure every temporary file is removed; if a rename fails (the directory changed
/// under the command), the files this call already renamed are removed too, so that no part of
/// the set is left. Throws InputError("<command line>", `option`, "cannot write 'PATH': why"):
/// exit 2 in the CLI. Paths must be distinct.
void write_files_atomically(const std::vector<OutputFile>& files, const std::string& option);

/// One file, as write_files_atomically: replaced whole or left as it was.
void write_file_atomically(const std::filesystem::path& path, const std::string& text, const std::string& option);

}  // namespace linkproof
