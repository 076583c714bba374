// libFuzzer target: the polygon scene reader (io/scene.h). Any bytes must give a scene or an
// InputError; a crash, a sanitizer report, a hang or another exception is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "linkproof/core/error.h"
#include "linkproof/io/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)linkproof::parse_polygon_scene(text, "fuzz.yaml");
  } catch (const linkproof::InputError&) {
  }
  return 0;
}
