// Scene files (TOML, comments allowed): parsing and strict validation into a SceneDesc.
// Every error — syntax, unknown or unused key, wrong type, value out of range, a referenced
// file that does not exist, an unknown material or shape name — throws SceneError with
// file:line:col.
#pragma once
#include <filesystem>
#include <string>

#include "renderer/scene/scene.h"

namespace hylios {

SceneDesc loadSceneFile(const std::filesystem::path& path);
/// `sourceName` appears in error locations; relative paths resolve against `baseDir`.
SceneDesc parseSceneText(const std::string& tomlText, const std::string& sourceName,
                         const std::filesystem::path& baseDir);

}  // namespace hylios
