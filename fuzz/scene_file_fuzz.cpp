// libFuzzer harness: parseSceneText (scene files, docs/scene-format.md) on arbitrary bytes, with
// relative paths resolved against scenes/test/ (so the seed scenes' mesh and specimen references
// resolve). Bad input must throw a std::exception (SceneError); anything else is a finding.
#include <cstddef>
#include <cstdint>
#include <exception>

#include "fuzz/fuzz_check.h"
#include "renderer/scene/scene_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hylios;
  try {
    (void)parseSceneText(fuzz::asText(data, size), "fuzz_scene.toml",
                         HYLIOS_SOURCE_DIR "/scenes/test");
  } catch (const std::exception&) {
    // rejected with a message: fine
  }
  return 0;
}
