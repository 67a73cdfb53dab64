// libFuzzer harness: parseSceneText (scene files, docs/scene-format.md) on arbitrary bytes, with
// relative paths resolved against scenes/test/ (so the seed scenes' mesh and specimen references
// resolve). Bad input must throw a std::exception (SceneError); anything else is a finding. An
// accepted scene must keep the limits of docs/scene-format.md ("Limits", issue 13): every
// coordinate and size within 1e7 scene units, unit_cm in [1e-6, 1e6], the film within 16384 per
// side and 64 Mpixel, channel wavelengths distinct to 1e-6 nm — so that extreme magnitudes
// (1e300, 1e-300, 1e20) never reach the tracer.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <set>

#include "fuzz/fuzz_check.h"
#include "renderer/scene/scene_file.h"
#include "renderer/scene/toml_table_reader.h"

namespace {

bool within(double v, double bound) { return std::isfinite(v) && std::fabs(v) <= bound; }

bool within(const glm::dvec3& v) {
  return within(v.x, hylios::kMaxSceneCoordinate) && within(v.y, hylios::kMaxSceneCoordinate) &&
         within(v.z, hylios::kMaxSceneCoordinate);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hylios;
  SceneDesc scene;
  try {
    scene = parseSceneText(fuzz::asText(data, size), "fuzz_scene.toml",
                           HYLIOS_SOURCE_DIR "/scenes/test");
  } catch (const std::exception&) {
    return 0;  // rejected with a message: fine
  }
  const double bound = kMaxSceneCoordinate;
  fuzz::require(scene.unitCm >= 1e-6 && scene.unitCm <= 1e6, "unit_cm in [1e-6, 1e6]");
  fuzz::require(
      within(scene.camera.position) && within(scene.camera.lookAt) && within(scene.camera.up),
      "camera vectors within the scene extent limit");
  fuzz::require(
      within(scene.camera.apertureRadius, bound) && within(scene.camera.focusDistance, bound),
      "camera distances within the limit");
  fuzz::require(scene.film.width >= 1 && scene.film.height >= 1 &&
                    scene.film.width <= kMaxFilmSide && scene.film.height <= kMaxFilmSide &&
                    static_cast<long long>(scene.film.width) * scene.film.height <= kMaxFilmPixels,
                "film within the resolution limits");
  std::set<long long> channels;
  for (const BandDesc& band : scene.film.bands)
    for (double nm : band.channelWavelengths())
      fuzz::require(std::isfinite(nm) && channels.insert(std::llround(nm * 1e6)).second,
                    "channel wavelengths finite and distinct to 1e-6 nm");
  for (const ShapeDesc& shape : scene.shapes) {
    fuzz::require(within(shape.centre) && within(shape.planePoint),
                  "shape positions within the limit");
    if (shape.kind == ShapeDesc::Kind::Sphere)
      fuzz::require(within(shape.radius, bound) && shape.radius > 0, "radius in (0, 1e7]");
    if (shape.kind == ShapeDesc::Kind::Plane)
      fuzz::require(within(shape.planeSize, bound) && shape.planeSize > 0, "size in (0, 1e7]");
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        fuzz::require(std::isfinite(shape.transform[c][r]), "finite transform");
  }
  for (const LightDesc& light : scene.lights)
    fuzz::require(within(light.position), "light positions within the limit");
  return 0;
}
