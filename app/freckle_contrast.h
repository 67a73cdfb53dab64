// How much the freckles of a render stand out (paper Fig. 1: accentuated at 365 nm, imperceptible
// at 1100 nm): the pixels whose centre ray meets freckled skin are split by the freckle field's
// melanin multiplier m there (renderer/tracing/freckle_field.h) into "on a freckle" (m at least
// halfway to the freckle gain) and "clear" (m = 1), and
//   contrast = 1 − mean(on) / mean(clear)
// of the panel's quantity (app/figure_job.h: radiance, or luminance Y of a colour band). 0: the
// freckles cannot be told from the skin around them on average; > 0: they are darker. Its
// standard error follows from the two means' (delta method; the film's halves give each one's).
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

#include "renderer/image/film.h"
#include "renderer/scene/scene.h"

namespace hylios {

struct FreckleContrast {
  double contrast = 0;
  double standardError = 0;
  std::size_t frecklePixels = 0, clearPixels = 0;
};

/// Which pixels see freckles: per pixel 1 (on a freckle), 0 (clear skin) or -1 (neither: no
/// skin with freckles, or the rim of a freckle). Empty when the scene's skin has no freckles.
std::vector<int> frecklePixelClasses(const SceneDesc& scene);

/// The contrast of `band` of a film rendered from `scene`; nothing when the scene has no freckles
/// or either pixel set is empty.
std::optional<FreckleContrast> freckleContrast(const SceneDesc& scene, const Film& film,
                                               std::size_t band);

}  // namespace hylios
