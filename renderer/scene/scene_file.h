// Scene files (TOML, comments allowed): parsing and strict validation into a SceneDesc.
// Every error — syntax, unknown or unused key, wrong type, value out of range, a referenced
// file that does not exist, an unknown material or shape name — throws SceneError with
// file:line:col.
#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "renderer/scene/scene.h"

namespace hylios {

/// Film limits, the same for scene files and the command line's --resolution: at most
/// kMaxFilmSide pixels per side and kMaxFilmPixels in all (docs/scene-format.md, "Limits").
constexpr int kMaxFilmSide = 16384;
constexpr long long kMaxFilmPixels = 1ll << 26;  // 64 Mpixel (8192 × 8192)

SceneDesc loadSceneFile(const std::filesystem::path& path);
/// `sourceName` appears in error locations; relative paths resolve against `baseDir`.
SceneDesc parseSceneText(const std::string& tomlText, const std::string& sourceName,
                         const std::filesystem::path& baseDir);

/// The keys the parser accepts, per table: "top level", "camera", "film", "film.band", "light",
/// "material" (+ "material.freckles", "material.melanin_map"), "shape" (+ "shape.transform"),
/// "integrator". docs/scene-format.md documents the same keys
/// (tests/renderer/scene_format_doc_test.cpp checks both ways).
const std::map<std::string, std::vector<std::string>>& sceneFileKeys();

}  // namespace hylios
