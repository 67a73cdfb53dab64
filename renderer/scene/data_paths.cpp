#include "renderer/scene/data_paths.h"

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace hylios {

std::filesystem::path dataRoot() {
  const char* fromEnvironment = std::getenv("HYLIOS_DATA_DIR");
  const std::filesystem::path root =
      (fromEnvironment && *fromEnvironment) ? fromEnvironment : HYLIOS_DEFAULT_DATA_DIR;
  if (!std::filesystem::is_directory(root / "assets"))
    throw std::runtime_error("data folder '" + root.string() +
                             "' has no assets/ (set HYLIOS_DATA_DIR to the hylios source tree)");
  return root;
}

}  // namespace hylios
