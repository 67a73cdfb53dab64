// The render's work-division hook (RenderDivision, renderer/tracing/integrator.h) that the MPI
// layer uses (app/mpi_render.h): each part renders only its tiles, and the parts' films added slot
// by slot are the undivided film bit for bit (each slot is filled by one part, x + 0 = x), also
// with the film's sample passes continued over two calls. The noise-target decision across parts
// needs concurrent parts: tests/app/mpi_commands_test.sh (mpi_render).
#include <gtest/gtest.h>

#include <vector>

#include "renderer/scene/scene_file.h"
#include "renderer/tracing/integrator.h"
#include "renderer/tracing/render_job.h"

namespace hylios {
namespace {

SceneDesc testScene() {
  RenderSettings settings;
  settings.width = 40;  // 3 × 3 tiles of 16 px, the last row and column partial
  settings.height = 36;
  settings.samplesPerPixel = 4;
  settings.seed = 5;
  return applyRenderSettings(
      loadSceneFile(std::string(HYLIOS_SOURCE_DIR) + "/scenes/test/skin_sphere_550.toml"),
      settings);
}

/// The films of `parts` parts, added slot by slot into a film of the scene.
Film summedParts(const SceneDesc& scene, const Integrator& integrator, std::size_t parts,
                 RenderStats& stats) {
  std::vector<double> sums, secondHalfSums;
  std::vector<std::uint32_t> counts, secondHalfCounts;
  int spp = 0;
  for (std::size_t part = 0; part < parts; ++part) {
    Film film(scene.film);
    RenderOptions options = quietRenderOptions("part");
    options.division.part = part;
    options.division.parts = parts;
    options.samplesPerPass = 3;  // two passes: 3 + 1 samples
    stats.add(integrator.render(film, options));
    if (part == 0) {
      sums.assign(film.sums().size(), 0.0);
      secondHalfSums = sums;
      counts.assign(film.counts().size(), 0);
      secondHalfCounts = counts;
    }
    for (std::size_t s = 0; s < sums.size(); ++s) {
      sums[s] += film.sums()[s];
      secondHalfSums[s] += film.secondHalfSums()[s];
      counts[s] += film.counts()[s];
      secondHalfCounts[s] += film.secondHalfCounts()[s];
    }
    spp = film.samplesPerPixelDone();
  }
  Film whole(scene.film);
  whole.setWholeBandSamples(integrator.estimator() == skin::Estimator::Spectral);
  whole.restoreState(sums, counts, secondHalfSums, secondHalfCounts, spp);
  return whole;
}

TEST(RenderDivision, PartsAddUpToTheUndividedFilmBitForBit) {
  const SceneDesc scene = testScene();
  std::vector<double> wavelengths;
  Film reference(scene.film);
  for (const FilmChannel& c : reference.channels()) wavelengths.push_back(c.wavelengthNm);
  const Integrator integrator(scene, wavelengths);
  const RenderStats whole = integrator.render(reference, quietRenderOptions("whole"));
  for (std::size_t parts : {2, 4, 11}) {  // 11 parts: two of them get no tile
    RenderStats stats;
    const Film summed = summedParts(scene, integrator, parts, stats);
    EXPECT_EQ(summed.sums(), reference.sums()) << parts << " parts";
    EXPECT_EQ(summed.secondHalfSums(), reference.secondHalfSums()) << parts << " parts";
    EXPECT_EQ(summed.counts(), reference.counts()) << parts << " parts";
    EXPECT_EQ(summed.secondHalfCounts(), reference.secondHalfCounts()) << parts << " parts";
    EXPECT_EQ(stats.paths, whole.paths) << parts << " parts";
    EXPECT_EQ(stats.skinWalks, whole.skinWalks) << parts << " parts";
  }
  EXPECT_EQ(whole.paths, 40u * 36u * 4u);
}

TEST(RenderDivision, APartRendersOnlyItsTilesAndBadPartsAreRefused) {
  const SceneDesc scene = testScene();
  Film film(scene.film);
  const Integrator integrator(scene, {film.channels()[0].wavelengthNm});
  RenderOptions options = quietRenderOptions("part");
  options.division.part = 1;
  options.division.parts = 3;
  integrator.render(film, options);
  // Tiles 1, 4, 7 of the 3 × 3: columns x in [16, 32) only.
  for (int y = 0; y < 36; ++y)
    for (int x = 0; x < 40; ++x)
      EXPECT_EQ(film.sampleCount(x, y, 0) > 0, x >= 16 && x < 32) << x << "," << y;
  options.division.part = 3;
  Film other(scene.film);
  EXPECT_THROW(integrator.render(other, options), std::invalid_argument);
}

}  // namespace
}  // namespace hylios
