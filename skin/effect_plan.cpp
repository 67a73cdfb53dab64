#include "skin/effect_plan.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "skin/core/statistics.h"
#include "skin/melanosome_path_lengths.h"
#include "skin/skin_simulation.h"

namespace hylios::skin {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kConfidenceZ = 3.0;  // τ⁺ = τ + 3 s.e.
constexpr std::uint64_t kPilotStream =
    0x5eed0f9e1a7b3c2dULL;  // keeps pilot streams apart from the main run's

/// Upper Wilson score bound (z = 3) of a binomial proportion `hits` / `trials`.
double wilsonUpper(std::uint64_t hits, std::uint64_t trials) {
  const double n = static_cast<double>(trials), p = static_cast<double>(hits) / n,
               z2 = kConfidenceZ * kConfidenceZ;
  const double centre = p + z2 / (2 * n);
  const double spread = kConfidenceZ * std::sqrt(p * (1 - p) / n + z2 / (4 * n * n));
  return std::min(1.0, (centre + spread) / (1 + z2 / n));
}

/// Per-layer path-length statistics of one pilot run.
struct PilotRun {
  std::uint64_t rays = 0, subsurfaceExits = 0;
  std::array<double, kLayerCount> sumCm{}, sumSquaresCm2{};
  std::array<std::uint64_t, kLayerCount> entered{};  ///< rays with ℓ_k > 0

  double meanCm(std::size_t k) const { return sumCm[k] / static_cast<double>(rays); }
  double standardErrorCm(std::size_t k) const {
    const double n = static_cast<double>(rays), m = meanCm(k);
    return n < 2 ? 0.0 : std::sqrt(std::fmax(0.0, sumSquaresCm2[k] / n - m * m) / (n - 1));
  }
  double enteredUpper(std::size_t k) const { return wilsonUpper(entered[k], rays); }
};

PilotRun runPilot(const SkinOptics& optics, const WalkOptions& walkOptions, double incidenceDeg,
                  std::size_t angleIndex, const PlanOptions& options) {
  // The pilot only estimates mean path lengths: tabulated melanosome absorption (the same law up to
  // the table's 0.2 % error on melanosome absorption) makes it 3-5x cheaper.
  WalkOptions pilotOptions = walkOptions;
  pilotOptions.tabulatedMelanosomes = true;
  const SkinWalk walk(optics, pilotOptions);
  const Vec3 incident = incidentDirection(incidenceDeg);
  const std::uint64_t stream =
      mix64(wavelengthStream(optics.wavelengthNm) ^ kPilotStream) + angleIndex;
  PilotRun run;
  run.rays = options.pilotRays;
  for (std::uint64_t i = 0; i < options.pilotRays; ++i) {
    Rng rng(options.seed, stream, i);
    LayerPathLengths lengths;
    const SkinPath path = walk.trace(incident, rng, &lengths);
    if (path.end == PathEnd::SubsurfaceReflection) ++run.subsurfaceExits;
    for (std::size_t k = 0; k < kLayerCount; ++k) {
      const double l = lengths.cm[k];
      run.sumCm[k] += l;
      run.sumSquaresCm2[k] += l * l;
      if (l > 0) ++run.entered[k];
    }
  }
  return run;
}

/// x rounded to 12 significant digits: the key melanosome_interaction.cpp gives the path-length
/// table, so that the planner and the tabulated walk share one table per (γ, ρ).
double pathLengthTableKey(double x) {
  const double scale = std::pow(10.0, 11 - std::floor(std::log10(x)));
  return std::round(x * scale) / scale;
}

/// Probability that one melanosome interaction in `layer` absorbs the ray (θo = 0: the only ones
/// that change it), from the path-length table (skin/melanosome_path_lengths.h):
/// p1 = mean of 1 − exp(−κL) over the table's samples, with its standard error; an interaction
/// meets m melanosomes in complexes, one when dispersed, and absorbs with 1 − (1 − p1)^count. The
/// upper value uses p1 + 3 s.e. (monotone in p1). Exactly 0 without interior absorption.
struct AbsorptionFraction {
  double estimate = 0, upper = 0;
};
AbsorptionFraction melanosomeAbsorptionFraction(const SkinOptics& optics, Layer layer) {
  const MelanosomeOptics& m = optics[layer].melanosome;
  const double kappa = optics.melanosomeInteriorMuA_perCm * m.semiMinorAxisCm;  // κ = μa·a
  if (!(kappa > 0)) return {};
  const auto table = MelanosomePathLengths::shared(
      pathLengthTableKey(m.semiMajorAxisCm / m.semiMinorAxisCm),
      pathLengthTableKey(optics.melaninRefractiveIndex / optics[layer].refractiveIndex));
  RunningStatistic absorbed;
  for (double lengthPerMinorAxis : table->pathLengths())
    absorbed.add(-std::expm1(-kappa * lengthPerMinorAxis));
  const double count = m.inComplexes ? static_cast<double>(m.melanosomesPerComplex) : 1.0;
  auto perInteraction = [count](double p1) {  // 1 − (1 − p)^count
    return -std::expm1(count * std::log1p(-std::min(1.0, p1)));
  };
  return {perInteraction(absorbed.mean()),
          perInteraction(absorbed.mean() + kConfidenceZ * absorbed.standardError())};
}

bool sameProcess(const PlannedEffect& a, const PlannedEffect& b) {
  return a.process == b.process &&
         (a.process == Process::SurfaceRoughness ||
          (a.layer == b.layer && (a.process != Process::Absorption || a.absorber == b.absorber)));
}

/// Adds (or raises to) τ, τ⁺ for a process of one optics and incidence.
void record(std::vector<PlannedEffect>& effects, PlannedEffect e) {
  for (PlannedEffect& existing : effects)
    if (sameProcess(existing, e)) {
      existing.opticalDepth = std::max(existing.opticalDepth, e.opticalDepth);
      existing.opticalDepthUpper = std::max(existing.opticalDepthUpper, e.opticalDepthUpper);
      return;
    }
  effects.push_back(e);
}

/// τ⁺ from τ and its standard error in layer k (see the header).
double upperDepth(double tau, double tauStandardError, const PilotRun& run, std::size_t k) {
  const double entered = run.enteredUpper(k);
  if (run.entered[k] < kMinPilotRaysInLayer) return entered;
  return std::min(tau + kConfidenceZ * tauStandardError, entered);
}

/// The processes of `optics` with their optical depths for one pilot run.
void recordProcesses(const SkinOptics& optics, const WalkOptions& walk, const PilotRun& run,
                     const std::array<AbsorptionFraction, kLayerCount>& melanosomeAbsorption,
                     std::vector<PlannedEffect>& effects) {
  for (Layer layer : kAllLayers) {
    const std::size_t k = index(layer);
    if (k > index(walk.deepestLayer)) break;
    const LayerOptics& lo = optics[layer];
    if (!(lo.thicknessCm > 0)) continue;
    const double meanCm = run.meanCm(k), seCm = run.standardErrorCm(k);
    auto add = [&](Process process, Absorber absorber, double mu_perCm) {
      PlannedEffect e;
      e.process = process;
      e.layer = layer;
      e.absorber = absorber;
      e.opticalDepth = mu_perCm * meanCm;  // τ_p = μ_p · E[ℓ_k]
      e.opticalDepthUpper = upperDepth(e.opticalDepth, mu_perCm * seCm, run, k);
      record(effects, e);
    };
    for (Absorber a : kAllAbsorbers)
      if (lo.muA_perCm[index(a)] > 0) add(Process::Absorption, a, lo.muA_perCm[index(a)]);
    if (walk.melanosomes && lo.melanosome.mu_perCm > 0) {
      if (optics.meanScatteringAngleRad == 0) {  // only absorbing interactions change the ray
        const AbsorptionFraction& p = melanosomeAbsorption[k];
        PlannedEffect e;
        e.process = Process::Melanosomes;
        e.layer = layer;
        e.opticalDepth = lo.melanosome.mu_perCm * meanCm * p.estimate;
        const double upper = lo.melanosome.mu_perCm * (meanCm + kConfidenceZ * seCm) * p.upper;
        e.opticalDepthUpper = run.entered[k] < kMinPilotRaysInLayer
                                  ? run.enteredUpper(k)
                                  : std::min(upper, run.enteredUpper(k));
        record(effects, e);
      } else {
        add(Process::Melanosomes, Absorber::Water, lo.melanosome.mu_perCm);
      }
    }
    if (walk.rayleigh && lo.muRayleigh_perCm > 0)
      add(Process::Rayleigh, Absorber::Water, lo.muRayleigh_perCm);
  }
  if (walk.roughSurface) {
    PlannedEffect e;
    e.process = Process::SurfaceRoughness;
    // Every ray meets the surface once, and again (at least) when it leaves through it.
    e.opticalDepth = 1.0 + static_cast<double>(run.subsurfaceExits) / static_cast<double>(run.rays);
    e.opticalDepthUpper = kInfinity;
    record(effects, e);
  }
}

void checkArguments(const std::vector<SkinOptics>& optics, double epsilon,
                    const PlanOptions& options) {
  if (!(epsilon >= 0 && epsilon <= 1))
    throw std::invalid_argument("effect plan: tolerance epsilon = " + std::to_string(epsilon) +
                                " must lie in [0, 1]");
  if (options.pilotRays == 0)
    throw std::invalid_argument("effect plan: the pilot needs at least one ray");
  if (options.incidenceDeg.empty())
    throw std::invalid_argument("effect plan: no pilot incidence given");
  for (double a : options.incidenceDeg)
    if (!(a >= 0 && a < 90))
      throw std::invalid_argument("effect plan: pilot incidence " + std::to_string(a) +
                                  "° must lie in [0°, 90°)");
  if (optics.empty()) throw std::invalid_argument("effect plan: no optics to plan");
  for (const SkinOptics& o : optics)
    if (o.wavelengthNm != optics.front().wavelengthNm)
      throw std::invalid_argument("effect plan: optics at " + std::to_string(o.wavelengthNm) +
                                  " and " + std::to_string(optics.front().wavelengthNm) +
                                  " nm cannot share a plan");
}

/// Processes whose events cost time (melanosome interactions, Rayleigh draws) come first: dropping
/// an absorber only removes a term from a sum and saves nothing.
bool costsTimePerEvent(Process p) { return p == Process::Melanosomes || p == Process::Rayleigh; }

/// Marks processes skipped while Σ τ⁺ ≤ ε (ε = 0: none): the costly ones first, each group in
/// increasing order of τ⁺.
double dropCheapest(std::vector<PlannedEffect>& effects, double epsilon) {
  std::vector<std::size_t> order(effects.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const bool costlyA = costsTimePerEvent(effects[a].process),
               costlyB = costsTimePerEvent(effects[b].process);
    if (costlyA != costlyB) return costlyA;
    return effects[a].opticalDepthUpper < effects[b].opticalDepthUpper;
  });
  double dropped = 0;
  if (epsilon <= 0) return dropped;
  for (std::size_t i : order) {
    const double upper = effects[i].opticalDepthUpper;
    if (!(dropped + upper <= epsilon)) continue;  // a smaller one further on may still fit
    effects[i].kept = false;
    dropped += upper;
  }
  return dropped;
}

std::string layerLabel(const PlannedEffect& e) {
  return e.process == Process::SurfaceRoughness ? "surface" : std::string(layerName(e.layer));
}

}  // namespace

std::string PlannedEffect::name() const {
  switch (process) {
    case Process::Absorption:
      return "absorption: " + std::string(absorberName(absorber));
    case Process::Melanosomes:
      return "melanosomes";
    case Process::Rayleigh:
      return "Rayleigh";
    case Process::SurfaceRoughness:
      return "surface roughness";
  }
  return "?";
}

std::size_t EffectPlan::droppedCount() const {
  return static_cast<std::size_t>(std::count_if(effects.begin(), effects.end(),
                                                [](const PlannedEffect& e) { return !e.kept; }));
}

SkinOptics EffectPlan::apply(const SkinOptics& other) const {
  SkinOptics out = other;
  for (const PlannedEffect& e : effects) {
    if (e.kept) continue;
    LayerOptics& lo = out.layers[index(e.layer)];
    switch (e.process) {
      case Process::Absorption:
        lo.muA_perCm[index(e.absorber)] = 0;
        lo.muATotal_perCm =
            std::accumulate(lo.muA_perCm.begin(), lo.muA_perCm.end(), 0.0);  // Eq. 3
        break;
      case Process::Melanosomes:
        lo.melanosome.mu_perCm = 0;
        break;
      case Process::Rayleigh:
        lo.muRayleigh_perCm = 0;
        break;
      case Process::SurfaceRoughness:
        break;  // a walk option (EffectPlan::walk)
    }
  }
  return out;
}

EffectPlan planEffects(const SkinOptics& optics, double epsilon, const PlanOptions& options) {
  return planEffects(std::vector<SkinOptics>{optics}, epsilon, options);
}

EffectPlan planEffects(const std::vector<SkinOptics>& optics, double epsilon,
                       const PlanOptions& options) {
  checkArguments(optics, epsilon, options);
  EffectPlan plan;
  plan.epsilon = epsilon;
  plan.wavelengthNm = optics.front().wavelengthNm;
  plan.pilotIncidenceDeg = options.incidenceDeg;
  for (const SkinOptics& o : optics) {
    std::array<AbsorptionFraction, kLayerCount> melanosomeAbsorption{};
    if (options.walk.melanosomes && o.meanScatteringAngleRad == 0)
      for (Layer layer : kAllLayers)
        if (o[layer].thicknessCm > 0 && o[layer].melanosome.mu_perCm > 0)
          melanosomeAbsorption[index(layer)] = melanosomeAbsorptionFraction(o, layer);
    for (std::size_t j = 0; j < options.incidenceDeg.size(); ++j) {
      const PilotRun run = runPilot(o, options.walk, options.incidenceDeg[j], j, options);
      plan.pilotRaysTraced += run.rays;
      recordProcesses(o, options.walk, run, melanosomeAbsorption, plan.effects);
    }
  }
  plan.droppedDepthBound = dropCheapest(plan.effects, epsilon);
  plan.walk = options.walk;
  for (const PlannedEffect& e : plan.effects)
    if (!e.kept && e.process == Process::SurfaceRoughness) plan.walk.roughSurface = false;
  plan.optics = plan.apply(optics.front());
  return plan;
}

std::string EffectPlan::explain() const {
  std::ostringstream out;
  char line[160];
  std::snprintf(line, sizeof line, "effect plan at %g nm, epsilon = %g (pilot: %llu rays at",
                wavelengthNm, epsilon, static_cast<unsigned long long>(pilotRaysTraced));
  out << line;
  for (std::size_t i = 0; i < pilotIncidenceDeg.size(); ++i)
    out << (i ? ", " : " ") << pilotIncidenceDeg[i];
  out << " deg incidence)\n";
  std::snprintf(line, sizeof line, "  %-30s %-20s %12s %12s  %s\n", "process", "layer", "tau",
                "bound", "plan");
  out << line;
  for (const PlannedEffect& e : effects) {
    std::snprintf(line, sizeof line, "  %-30s %-20s %12.4g %12.4g  %s\n", e.name().c_str(),
                  layerLabel(e).c_str(), e.opticalDepth, e.opticalDepthUpper,
                  e.kept ? "kept" : "skipped");
    out << line;
  }
  std::snprintf(
      line, sizeof line,
      "  skipped %zu of %zu processes; bound on any exit probability |dR| <= %.3g (epsilon %g)\n",
      droppedCount(), effects.size(), droppedDepthBound, epsilon);
  out << line;
  return out.str();
}

std::string EffectPlan::summary() const {
  std::ostringstream out;
  char head[96];
  std::snprintf(head, sizeof head, "%g nm: kept %zu of %zu, bound %.3g", wavelengthNm,
                effects.size() - droppedCount(), effects.size(), droppedDepthBound);
  out << head;
  bool first = true;
  for (const PlannedEffect& e : effects) {
    if (e.kept) continue;
    out << (first ? "; skipped " : ", ") << e.name() << " (" << layerLabel(e) << ")";
    first = false;
  }
  out << "\n";
  return out.str();
}

}  // namespace hylios::skin
