// `hylios slab`: the generic layered-slab Monte Carlo (MCML's problem) from the command line;
// writes one CSV row of reflectance, transmittance and absorptance with standard errors.
#include <fmt/format.h>

#include <cstdint>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/enum_option.h"
#include "app/option_checks.h"
#include "app/slab_layer_spec.h"
#include "skin/core/atomic_file.h"
#include "skin/core/thread_limit.h"
#include "skin/layered_slab.h"

namespace hylios {
namespace {

struct SlabOptions {
  double nAbove = 1.0, nBelow = 1.0, angleDeg = 0.0;
  std::vector<std::string> layers;
  std::uint64_t rays = 1000000, seed = 1;
  std::string out;
  skin::AbsorptionScheme scheme = skin::AbsorptionScheme::WeightWithRoulette;
  bool diffuse = false, scalar = false;
  int threads = 0;
};

std::string csvFor(const skin::SlabResult& r) {
  std::string header =
      "specular_reflectance,diffuse_reflectance,diffuse_reflectance_stderr,transmittance,"
      "transmittance_stderr,unscattered_transmittance,absorptance,absorptance_stderr";
  std::string row =
      fmt::format("{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}", r.specularReflectance,
                  r.diffuseReflectance.mean, r.diffuseReflectance.standardError,
                  r.transmittance.mean, r.transmittance.standardError,
                  r.unscatteredTransmittance.mean, r.absorptance.mean, r.absorptance.standardError);
  for (std::size_t l = 0; l < r.layerAbsorptance.size(); ++l) {
    header += fmt::format(",absorptance_layer{0},absorptance_layer{0}_stderr", l + 1);
    row += fmt::format(",{:.9g},{:.9g}", r.layerAbsorptance[l].mean,
                       r.layerAbsorptance[l].standardError);
  }
  header += ",event_limited";
  row += fmt::format(",{:.9g}", r.eventLimited.mean);
  return header + "\n" + row + "\n";
}

void runSlab(const SlabOptions& o) {
  checkOutputs({{"--out", o.out}});
  skin::SlabProblem problem;
  problem.refractiveIndexAbove = o.nAbove;
  problem.refractiveIndexBelow = o.nBelow;
  problem.incidenceAngleDeg = o.angleDeg;
  problem.diffuseIncidence = o.diffuse;
  for (const std::string& spec : o.layers) problem.layers.push_back(parseSlabLayerSpec(spec));
  skin::SlabRunOptions run;
  run.photons = o.rays;
  run.seed = o.seed;
  run.scheme = o.scheme;
  run.laneWalk = !o.scalar;
  if (o.rays == 0) throw std::invalid_argument("--rays must be at least 1");
  if (o.threads < 0) throw std::invalid_argument("--threads must be >= 0 (0: all cores)");
  const ThreadLimit threadLimit(o.threads);
  const skin::SlabResult result = skin::simulateLayeredSlab(problem, run);
  writeTextAtomically(o.out, csvFor(result));
  if (result.eventLimited.mean > 0)
    std::cerr << fmt::format(
        "hylios: warning: {:.3g} of the incident light was still travelling after {} events per "
        "packet (a thick layer that scatters and hardly absorbs); it is in the CSV's "
        "event_limited, not in Rd, Tt or A\n",
        result.eventLimited.mean, skin::kSlabEventLimit);
  std::cout << fmt::format(
      "Rsp {:.6f}  Rd {:.6f} ± {:.6f}  Tt {:.6f} ± {:.6f}  A {:.6f} ± {:.6f}  -> {}\n",
      result.specularReflectance, result.diffuseReflectance.mean,
      result.diffuseReflectance.standardError, result.transmittance.mean,
      result.transmittance.standardError, result.absorptance.mean, result.absorptance.standardError,
      o.out);
}

}  // namespace

void registerSlabCommand(CLI::App& app) {
  auto options = std::make_shared<SlabOptions>();
  CLI::App* sub = app.add_subcommand(
      "slab", "Monte Carlo of a layered slab (MCML's problem): Rd, Tt, absorptance per layer");
  sub->add_option("--above", options->nAbove, "refractive index of the ambient above")
      ->check(finiteRange(1.0, 10.0))
      ->capture_default_str();
  sub->add_option("--below", options->nBelow, "refractive index of the ambient below")
      ->check(finiteRange(1.0, 10.0))
      ->capture_default_str();
  sub->add_option("--layer", options->layers,
                  "a layer, top first: n=..,mua=..(1/cm),mus=..(1/cm),g=..,d=..(cm or inf); repeat")
      ->required();
  sub->add_option("--rays", options->rays, "photon packets")
      ->check(unsignedRange(1, std::uint64_t{1} << 40))
      ->capture_default_str();
  sub->add_option("--angle", options->angleDeg, "incidence angle from the normal, degrees [0, 90)")
      ->check(finiteRange(0.0, 89.999))
      ->capture_default_str();
  sub->add_flag("--diffuse", options->diffuse,
                "diffuse (Lambertian) illumination instead of a beam");
  sub->add_option("--seed", options->seed, "random seed in [0, 2^63-1]")
      ->check(seedRange())
      ->capture_default_str();
  addEnumOption(*sub, "--scheme", options->scheme, skin::kAbsorptionSchemeNames,
                "absorption scoring: weighted (default; absorption as weight, MCML's implicit "
                "capture with roulette) or analog (the packet dies where it is absorbed)");
  sub->add_flag("--scalar", options->scalar,
                "weighted scheme: trace one packet at a time in double precision (the reference) "
                "instead of eight at once in single-precision lanes");
  sub->add_option("--threads", options->threads, "worker threads (0: all cores)")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
  sub->add_option("--out", options->out, "output CSV file")->required();
  sub->callback([options] { runSlab(*options); });
}

}  // namespace hylios
