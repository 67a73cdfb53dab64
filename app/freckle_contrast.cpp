#include "app/freckle_contrast.h"

#include <cmath>
#include <memory>

#include "app/figure_job.h"
#include "renderer/tracing/camera.h"
#include "renderer/tracing/embree_scene.h"
#include "renderer/tracing/freckle_field.h"

namespace hylios {

std::vector<int> frecklePixelClasses(const SceneDesc& scene) {
  // The freckle field of each shape's material (null: not freckled skin).
  std::vector<std::unique_ptr<FreckleField>> fields(scene.shapes.size());
  bool any = false;
  for (std::size_t s = 0; s < scene.shapes.size(); ++s)
    for (const MaterialDesc& m : scene.materials)
      if (m.name == scene.shapes[s].material && m.kind == MaterialDesc::Kind::Skin &&
          m.skin.freckles.densityPerCm2 > 0) {
        fields[s] = std::make_unique<FreckleField>(m.skin.freckles, m.where);
        any = true;
      }
  if (!any) return {};
  const EmbreeScene geometry(scene);
  const Camera camera(scene.camera, scene.film.width, scene.film.height);
  std::vector<int> classes(static_cast<std::size_t>(scene.film.width) * scene.film.height, -1);
  for (int y = 0; y < scene.film.height; ++y)
    for (int x = 0; x < scene.film.width; ++x) {
      const auto hit = geometry.intersect(camera.generateRay(x + 0.5, y + 0.5, 0.5, 0.5));
      if (!hit || !fields[hit->shape]) continue;
      const FreckleField& field = *fields[hit->shape];
      const double m = field.multiplier(hit->position * scene.unitCm);
      const double gain = field.maxMultiplier() > 1 ? field.maxMultiplier() : field.minMultiplier();
      int& c = classes[static_cast<std::size_t>(y) * scene.film.width + x];
      if (m == 1)
        c = 0;
      else if (std::fabs(m - 1) >= 0.5 * std::fabs(gain - 1))
        c = 1;
    }
  return classes;
}

std::optional<FreckleContrast> freckleContrast(const SceneDesc& scene, const Film& film,
                                               std::size_t band) {
  const std::vector<int> classes = frecklePixelClasses(scene);
  if (classes.empty() || classes.size() != film.coverage().size()) return std::nullopt;
  std::vector<bool> on(classes.size()), clear(classes.size());
  for (std::size_t p = 0; p < classes.size(); ++p) {
    on[p] = classes[p] == 1 && film.coverage()[p];
    clear[p] = classes[p] == 0 && film.coverage()[p];
  }
  const PanelMean f = panelMean(film, band, &on), c = panelMean(film, band, &clear);
  if (f.pixels == 0 || c.pixels == 0 || !(c.mean > 0)) return std::nullopt;
  FreckleContrast result;
  const double ratio = f.mean / c.mean;
  result.contrast = 1 - ratio;
  result.standardError = std::fabs(ratio) * std::hypot(f.mean != 0 ? f.standardError / f.mean : 0.0,
                                                       c.standardError / c.mean);
  result.frecklePixels = f.pixels;
  result.clearPixels = c.pixels;
  return result;
}

}  // namespace hylios
