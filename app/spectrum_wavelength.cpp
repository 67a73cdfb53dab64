#include "app/spectrum_wavelength.h"

#include "app/spectral_table_spectrum.h"
#include "renderer/tracing/exit_table_cache.h"
#include "renderer/tracing/skin_table_cache.h"

namespace hylios {

skin::SkinTally exitTableTally(const skin::SkinWalk& walk, double incidenceDeg, std::uint64_t rays,
                               std::uint64_t seed) {
  const auto table = ExitTableCache::shared().get(walk, SkinTableCache::curveSettings());
  return sampleTableTally(*table, incidenceDeg, rays, seed);
}

SpectrumWavelengthResult simulateSpectrumWavelength(const skin::SkinOptics& optics,
                                                    const SpectrumWavelengthSettings& settings) {
  SpectrumWavelengthResult result;
  if (settings.effectTolerance != 0 || settings.planAlways) {
    skin::PlanOptions options;
    options.incidenceDeg = {settings.incidenceDeg};
    options.pilotRays = kSpectrumPilotRays;
    options.seed = settings.seed;
    result.plan = skin::planEffects(optics, settings.effectTolerance, options);
  }
  skin::WalkRunOptions run;
  run.incidenceDeg = settings.incidenceDeg;
  run.rays = settings.rays;
  run.seed = settings.seed;
  if (result.plan) run.walk = result.plan->walk;
  const skin::SkinOptics& walked = result.plan ? result.plan->optics : optics;
  result.tally = settings.skinMode == skin::SkinMode::Table
                     ? exitTableTally(skin::SkinWalk(walked, run.walk), settings.incidenceDeg,
                                      settings.rays, settings.seed)
                     : skin::simulateSkin(walked, run);
  return result;
}

}  // namespace hylios
