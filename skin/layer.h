// The six skin layers of HyLIoS (paper Sec. 4, Fig. 4), top to bottom.
#pragma once
#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

namespace hylios::skin {

enum class Layer : std::size_t {
  StratumCorneum = 0,
  StratumGranulosum,
  StratumSpinosum,
  StratumBasale,
  PapillaryDermis,
  ReticularDermis,
};
inline constexpr std::size_t kLayerCount = 6;

inline constexpr std::array<Layer, kLayerCount> kAllLayers = {
    Layer::StratumCorneum, Layer::StratumGranulosum, Layer::StratumSpinosum,
    Layer::StratumBasale,  Layer::PapillaryDermis,   Layer::ReticularDermis};

/// snake_case name used in files and CSV columns, e.g. "stratum_corneum".
constexpr std::string_view layerName(Layer layer) {
  constexpr std::array<std::string_view, kLayerCount> names = {
      "stratum_corneum", "stratum_granulosum", "stratum_spinosum",
      "stratum_basale",  "papillary_dermis",   "reticular_dermis"};
  return names[static_cast<std::size_t>(layer)];
}
constexpr std::size_t index(Layer layer) { return static_cast<std::size_t>(layer); }
/// The three epidermal layers that hold melanin (granulosum, spinosum, basale).
constexpr bool isPigmentedEpidermis(Layer l) {
  return l == Layer::StratumGranulosum || l == Layer::StratumSpinosum || l == Layer::StratumBasale;
}

}  // namespace hylios::skin
