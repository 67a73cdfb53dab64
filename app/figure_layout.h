// The layout of a figure's contact sheet from its scenes alone (issue 17): what varies between the
// scenes, the order of the panels, their captions and the sheet's title. Nothing is taken from
// file names.
//
// Each scene is described by its quantities (sceneQuantities): every band (its wavelength or
// range), and for each skin material the specimen, every specimen override (the last one of a
// key wins, as the parser applies them in file order), the dehydration (the override and the
// material's own water_reduction_percent combined as the model combines them: 1 − (1 − a)(1 − b))
// and the freckle density. A quantity varies when its value differs between the scenes, or when
// some scenes lack it (an override left out means the specimen's own value, shown "as S1").
//   * Order: by the varied quantities, in the order they first appear in the first scene: numbers
//     ascending (the band by its shortest wavelength: UV, visible, IR), a missing override first;
//     ties keep the order given.
//   * Caption of a panel: the varied quantities' texts ("epidermal melanin 7 %", "water −20 %",
//     "365 nm"); the file stem when nothing varies between several scenes.
//   * Title: what the panels share, e.g. "specimen S1 · 365 nm".
// A scene with several bands gives one panel per band (a row per scene); the band is then named
// in each caption.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "renderer/scene/scene.h"

namespace hylios {

/// One thing that can vary between the scenes of a figure.
struct SceneQuantity {
  std::string key;               ///< "band", "skin/melanosome_percent", … (unique per scene)
  std::optional<double> number;  ///< the sort value (nm for a band); unset: sorted by text
  std::string text;              ///< the caption text, e.g. "epidermal melanin 7 %"
};

/// The quantities of a scene in a fixed order: bands, then per skin material the specimen, its
/// overrides (in file order of their first mention), water, freckles.
std::vector<SceneQuantity> sceneQuantities(const SceneDesc& scene);

/// The caption text of a band: "365 nm", or "visible 380–780 nm" for a colour band.
std::string bandText(const BandDesc& band);

/// The caption text of a specimen override, e.g. ("melanosome_percent", 7) → "epidermal melanin
/// 7 %", ("water_reduction_percent", 20) → "water −20 %"; unknown keys read "key = value".
std::string overrideText(const std::string& key, double value);

struct FigureLayout {
  std::vector<std::size_t> order;     ///< indices into the scenes, in panel order
  std::vector<std::string> captions;  ///< one per scene, in panel order (order[i]'s caption)
  std::vector<std::string> varied;    ///< keys of the varied quantities, in sort priority
  std::string title;                  ///< what every scene shares, "" when nothing
  bool bandInCaptions = false;        ///< the band varies, or a scene has several bands
};

/// The layout of a figure made of `scenes` (at least one).
FigureLayout layoutFigure(const std::vector<SceneDesc>& scenes);

}  // namespace hylios
