// Parts of the scenes the renderer tests build in code (tests/renderer, tests/app): a constant
// spectrum, one-wavelength and range bands, and the skin sphere test scene at a given size.
#pragma once
#include <filesystem>
#include <string>

#include "renderer/scene/scene.h"
#include "renderer/scene/scene_file.h"

namespace hylios::test {

/// A constant spectrum of `value` (an emission or a reflectance).
inline EmissionDesc constantSpectrum(double value) {
  EmissionDesc e;
  e.kind = EmissionDesc::Kind::Constant;
  e.scale = value;
  return e;
}

/// A band of one wavelength, `nm`, named "b".
inline BandDesc singleWavelengthBand(double nm) {
  BandDesc b;
  b.name = "b";
  b.minNm = b.maxNm = nm;
  return b;
}

/// A band `name` over [minNm, maxNm] every `stepNm`, previews over [0, 1].
inline BandDesc rangeBand(const std::string& name, double minNm, double maxNm, double stepNm) {
  BandDesc b;
  b.name = name;
  b.minNm = minNm;
  b.maxNm = maxNm;
  b.stepNm = stepNm;
  b.previewMin = 0;
  b.previewMax = 1;
  return b;
}

/// scenes/test/skin_sphere_550.toml at side × side pixels and `spp` samples per pixel.
inline SceneDesc skinSphereScene(int side, int spp) {
  SceneDesc scene =
      loadSceneFile(std::filesystem::path(HYLIOS_SOURCE_DIR) / "scenes/test/skin_sphere_550.toml");
  scene.film.width = scene.film.height = side;
  scene.film.samplesPerPixel = spp;
  return scene;
}

}  // namespace hylios::test
