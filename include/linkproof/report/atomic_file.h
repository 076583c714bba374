// Writing an output file so that it is never half-written.
#pragma once

#include <filesystem>
#include <string>

namespace linkproof {

/// Writes `text` to a temporary file beside `path` ("." + name + ".tmp-" + pid), flushes and
/// closes it, and renames it onto `path` (atomic on one file system). On any failure (a full
/// disk, a missing directory) the temporary file is removed, `path` is left as it was, and
/// InputError(`option`, path, problem) is thrown: exit 2 in the CLI.
void write_file_atomically(const std::filesystem::path& path, const std::string& text, const std::string& option);

}  // namespace linkproof
