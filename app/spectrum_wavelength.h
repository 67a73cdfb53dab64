// One wavelength of `hylios spectrum` (and of the Python hylios.spectrum) when it is not run by
// the spectral walk: the effect plan (skin/effect_plan.h) and then either the planned walk or
// rays sampled from the exit table of the planned walk (table mode, skin/exit_table.h).
#pragma once
#include <cstdint>
#include <optional>

#include "skin/effect_plan.h"
#include "skin/skin_mode.h"
#include "skin/skin_optics.h"
#include "skin/skin_simulation.h"
#include "skin/skin_tally.h"
#include "skin/skin_walk.h"

namespace hylios {

/// Pilot rays of the effect planner per wavelength (skin/effect_plan.h).
inline constexpr std::uint64_t kSpectrumPilotRays = 2000;

struct SpectrumWavelengthSettings {
  double incidenceDeg = 45;
  std::uint64_t rays = 100000;
  std::uint64_t seed = 1;
  double effectTolerance = skin::kDefaultEffectTolerance;  ///< ε; 0: the full model
  bool planAlways = false;  ///< plan even at ε = 0 (for --explain); else no pilot at ε = 0
  skin::SkinMode skinMode = skin::SkinMode::Walk;
};

struct SpectrumWavelengthResult {
  skin::SkinTally tally;
  std::optional<skin::EffectPlan> plan;  ///< when one was made
};

/// Table mode: `rays` rays sampled from the exit table of `walk` (ExitTableCache::shared(), the
/// renderer's table settings), ray i on Rng(seed, wavelengthStream(λ), i) like the walk.
skin::SkinTally exitTableTally(const skin::SkinWalk& walk, double incidenceDeg, std::uint64_t rays,
                               std::uint64_t seed);

/// The tally at the wavelength of `optics`: the planned optics and switches (the full model when
/// ε = 0 and no plan is asked for), walked or (table mode) sampled from their exit table.
SpectrumWavelengthResult simulateSpectrumWavelength(const skin::SkinOptics& optics,
                                                    const SpectrumWavelengthSettings& settings);

}  // namespace hylios
