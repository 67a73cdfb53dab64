// Which numbers a camera path draws (issue 12, item 3; renderer/tracing/pixel_sampler.h): every
// number independent (xoshiro256++ per pixel and sample, as before), or the first dimensions from
// Owen-scrambled Sobol' points per pixel. Named "independent" / "sobol" in scene files
// (`[integrator] sampler`) and on the command line (`--sampler`). sobol is the default: at equal
// spp it was never noisier than independent in docs/benchmarks.md's measurements, and less noisy
// wherever the integrator's own decisions matter (direct light, the first bounce).
#pragma once
#include "skin/core/enum_names.h"

namespace hylios {

enum class SamplerKind { Independent, Sobol };

inline constexpr EnumNames<SamplerKind, 2> kSamplerNames{
    {{SamplerKind::Independent, "independent"}, {SamplerKind::Sobol, "sobol"}}};

}  // namespace hylios
