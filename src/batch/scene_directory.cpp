#include "batch/scene_directory.h"

#include <filesystem>
#include <fstream>
#include <system_error>

namespace linkproof {

void create_scene_directory(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(dir, "scene directory", "cannot create the directory: " + ec.message());
}

void write_scene_file(const std::string& dir, const std::string& name, const std::string& yaml) {
  // A failure to create the directory shows as the file that cannot be written.
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  const std::string path = (std::filesystem::path(dir) / (name + ".yaml")).string();
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  f << yaml;
  f.close();
  if (!f) throw InputError(path, "scene directory", "cannot write the scene file");
}

int write_counterexample_scenes(const std::string& dir, const TopologySweepReport& report) {
  create_scene_directory(dir);
  int written = 0;
  for (const SampleResult& c : report.run.claims)
    if (c.counterexample) {
      write_scene_file(dir, c.counterexample->scene.name, c.counterexample->scene_yaml);
      ++written;
    }
  return written;
}

}  // namespace linkproof
