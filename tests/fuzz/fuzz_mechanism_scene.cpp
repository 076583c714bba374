// libFuzzer target: the mechanism scene reader (io/mechanism_scene.h), and the choice between
// the two readers that `check` makes. Any bytes must give a scene or an InputError.
#include <cstddef>
#include <cstdint>
#include <string>

#include "linkproof/core/error.h"
#include "linkproof/io/mechanism_scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  (void)linkproof::is_mechanism_scene_text(text);
  try {
    (void)linkproof::parse_mechanism_scene(text, "fuzz.yaml");
  } catch (const linkproof::InputError&) {
  }
  return 0;
}
