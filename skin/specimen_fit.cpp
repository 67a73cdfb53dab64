#include "skin/specimen_fit.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "skin/skin_optics.h"
#include "skin/spectral_simulation.h"

namespace hylios::skin {
namespace {

constexpr std::array<Layer, 3> kPigmented = {Layer::StratumGranulosum, Layer::StratumSpinosum,
                                             Layer::StratumBasale};
constexpr std::array<Layer, 2> kDermis = {Layer::PapillaryDermis, Layer::ReticularDermis};

std::vector<FitQuantity> buildQuantities() {
  // Bounds: docs/interpretations.md, "Fitting a specimen" (one row per quantity, with sources).
  return {
      {"melanosome", "%", 1.0, 10.0,
       "Sec. 3.2 [Lis13]: melanosomes occupy 1 % (light) to 10 % (dark) of the epidermis"},
      {"colloidal", "%", 0.0, 15.0, "Table 1 span 0.8-15 % [AAB*02, KSZC91, Pat95]"},
      {"blood", "%", 0.2, 5.0, "Table 1 span 0.2-2.5 % [Fle00, Jac96], upper bound doubled"},
      {"oxygenation", "%", 50.0, 100.0,
       "Table 1 uses 75-95 % [Ang01]; cutaneous blood lies between venous and arterial saturation"},
      {"water_reduction", "%", 0.0, 40.0, "Sec. 5 / Fig. 14 dehydration range 0-40 %"},
      {"stratum_corneum_thickness", "cm", 0.0002, 0.002,
       "Table 1 span 2-10 um [Dif80, AP82], up to 20 um on most body sites [AP82]"},
      {"epidermis_thickness", "cm", 0.002, 0.015,
       "Table 1 span 21-99 um for the three layers [RR10, Shi07], widened by half"},
      {"papillary_dermis_thickness", "cm", 0.005, 0.035,
       "Table 1 span 0.01-0.023 cm [AP81], widened by half"},
      {"reticular_dermis_thickness", "cm", 0.05, 0.3,
       "Table 1 span 0.1-0.2 cm [AP81]; dermis up to 4 mm (Sec. 3 [AP82])"},
  };
}

template <std::size_t N>
double maxOver(const std::array<double, kLayerCount>& a, const std::array<Layer, N>& layers) {
  double m = 0;
  for (Layer l : layers) m = std::max(m, a[index(l)]);
  return m;
}
template <std::size_t N>
double sumOver(const std::array<double, kLayerCount>& a, const std::array<Layer, N>& layers) {
  double s = 0;
  for (Layer l : layers) s += a[index(l)];
  return s;
}
/// Sets `layers` of `out` to `start`'s profile scaled so that its maximum (or sum) is `value`;
/// a profile that is all zero becomes uniform.
template <std::size_t N>
void setProfile(const std::array<double, kLayerCount>& start, std::array<double, kLayerCount>& out,
                const std::array<Layer, N>& layers, double value, bool bySum) {
  const double ref = bySum ? sumOver(start, layers) : maxOver(start, layers);
  for (Layer l : layers) {
    const double share =
        ref > 0 ? start[index(l)] / ref : (bySum ? 1.0 / static_cast<double>(layers.size()) : 1.0);
    out[index(l)] = value * share;
  }
}

/// Solves the symmetric positive system A x = b (n ≤ 9) by Cholesky; false if not positive.
bool solveCholesky(std::vector<double> a, std::vector<double> b, std::size_t n,
                   std::vector<double>& x) {
  for (std::size_t j = 0; j < n; ++j) {
    double d = a[j * n + j];
    for (std::size_t k = 0; k < j; ++k) d -= a[j * n + k] * a[j * n + k];
    if (!(d > 0)) return false;
    a[j * n + j] = std::sqrt(d);
    for (std::size_t i = j + 1; i < n; ++i) {
      double s = a[i * n + j];
      for (std::size_t k = 0; k < j; ++k) s -= a[i * n + k] * a[j * n + k];
      a[i * n + j] = s / a[j * n + j];
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    double s = b[i];
    for (std::size_t k = 0; k < i; ++k) s -= a[i * n + k] * b[k];
    b[i] = s / a[i * n + i];
  }
  x.assign(n, 0);
  for (std::size_t i = n; i-- > 0;) {
    double s = b[i];
    for (std::size_t k = i + 1; k < n; ++k) s -= a[k * n + i] * x[k];
    x[i] = s / a[i * n + i];
  }
  return true;
}

double sumSquares(const std::vector<double>& r) {
  double s = 0;
  for (double v : r) s += v * v;
  return s;
}

}  // namespace

const std::vector<FitQuantity>& fitQuantities() {
  static const std::vector<FitQuantity> q = buildQuantities();
  return q;
}

const FitQuantity& fitQuantity(const std::string& name) {
  for (const auto& q : fitQuantities())
    if (q.name == name) return q;
  std::string list;
  for (const auto& q : fitQuantities()) list += (list.empty() ? "" : ", ") + q.name;
  throw FitError(fmt::format("unknown fit quantity '{}' (known: {})", name, list));
}

double fitQuantityValue(const Specimen& s, const std::string& name) {
  if (name == "melanosome") return 100 * maxOver(s.melanosomeFraction, kPigmented);
  if (name == "colloidal") return 100 * maxOver(s.colloidalMelaninFraction, kPigmented);
  if (name == "blood") return 100 * maxOver(s.bloodFraction, kDermis);
  if (name == "oxygenation") return 100 * s.oxygenatedBloodFraction;
  if (name == "water_reduction") return 100 * s.waterReduction;
  if (name == "stratum_corneum_thickness") return s.thicknessCm[index(Layer::StratumCorneum)];
  if (name == "epidermis_thickness") return sumOver(s.thicknessCm, kPigmented);
  if (name == "papillary_dermis_thickness") return s.thicknessCm[index(Layer::PapillaryDermis)];
  if (name == "reticular_dermis_thickness") return s.thicknessCm[index(Layer::ReticularDermis)];
  fitQuantity(name);  // throws
  return 0;
}

void setFitQuantity(const Specimen& start, Specimen& s, const std::string& name, double v) {
  if (!std::isfinite(v)) throw FitError(fmt::format("{} = {} is not finite", name, v));
  if (name == "melanosome")
    return setProfile(start.melanosomeFraction, s.melanosomeFraction, kPigmented, v / 100, false);
  if (name == "colloidal")
    return setProfile(start.colloidalMelaninFraction, s.colloidalMelaninFraction, kPigmented,
                      v / 100, false);
  if (name == "blood")
    return setProfile(start.bloodFraction, s.bloodFraction, kDermis, v / 100, false);
  if (name == "oxygenation") {
    s.oxygenatedBloodFraction = v / 100;
    return;
  }
  if (name == "water_reduction") {
    s.waterReduction = v / 100;
    return;
  }
  if (name == "stratum_corneum_thickness") {
    s.thicknessCm[index(Layer::StratumCorneum)] = v;
    return;
  }
  if (name == "epidermis_thickness")
    return setProfile(start.thicknessCm, s.thicknessCm, kPigmented, v, true);
  if (name == "papillary_dermis_thickness") {
    s.thicknessCm[index(Layer::PapillaryDermis)] = v;
    return;
  }
  if (name == "reticular_dermis_thickness") {
    s.thicknessCm[index(Layer::ReticularDermis)] = v;
    return;
  }
  fitQuantity(name);  // throws
}

std::vector<Estimate> modelReflectance(const Specimen& specimen, const SpectralDatabase& spectra,
                                       const std::vector<double>& wavelengthNm,
                                       const FitOptions& options) {
  std::vector<SkinOptics> optics;
  optics.reserve(wavelengthNm.size());
  for (double w : wavelengthNm) optics.push_back(computeSkinOptics(specimen, spectra, w));
  SpectralRunOptions run;
  run.incidenceDeg = options.incidenceDeg;
  run.rays = options.rays;
  run.seed = options.seed;
  run.walk = options.walk;
  run.splitRayleighWithoutDeflection = true;  // a scalar curve (skin/spectral_simulation.h)
  const std::vector<SkinTally> tallies = simulateSkinSpectral(optics, run);
  std::vector<Estimate> r;
  r.reserve(tallies.size());
  for (const auto& t : tallies) r.push_back(t.reflectance());
  return r;
}

namespace {

/// Per interior quantity (in the [0, 1] parameter units): the variance of the optimum caused by
/// the model curve's Monte Carlo noise at options.rays, from kFitNoiseBatches independent curves
/// of rays/kFitNoiseBatches rays each, projected by (JᵀJ)⁻¹Jᵀ (`a` = JᵀJ over `interior`).
std::vector<double> modelNoiseVariance(const Specimen& optimum, const SpectralDatabase& spectra,
                                       const std::vector<double>& wavelengthNm,
                                       const FitOptions& options, const std::vector<double>& jac,
                                       std::size_t n, const std::vector<std::size_t>& interior,
                                       const std::vector<double>& a) {
  const std::size_t f = interior.size(), m = wavelengthNm.size();
  FitOptions batch = options;
  batch.rays = std::max<std::uint64_t>(1, options.rays / kFitNoiseBatches);
  std::vector<std::vector<double>> shifts;  // per batch: (JᵀJ)⁻¹Jᵀ c_b
  for (std::uint64_t b = 0; b < kFitNoiseBatches; ++b) {
    batch.seed = options.seed + kFitNoiseSeedOffset + b;
    const std::vector<Estimate> curve = modelReflectance(optimum, spectra, wavelengthNm, batch);
    std::vector<double> jtc(f, 0), shift;
    for (std::size_t i = 0; i < m; ++i)
      for (std::size_t k = 0; k < f; ++k) jtc[k] += jac[i * n + interior[k]] * curve[i].mean;
    if (!solveCholesky(a, jtc, f, shift))
      return std::vector<double>(f, std::numeric_limits<double>::infinity());
    shifts.push_back(shift);
  }
  std::vector<double> variance(f, 0);
  const double batches = static_cast<double>(kFitNoiseBatches);
  for (std::size_t k = 0; k < f; ++k) {
    double mean = 0;
    for (const auto& shift : shifts) mean += shift[k] / batches;
    double squares = 0;
    for (const auto& shift : shifts) squares += (shift[k] - mean) * (shift[k] - mean);
    // Sample variance of a batch, then scaled to a curve of `rays` (kFitNoiseBatches× the rays).
    variance[k] = squares / (batches - 1) * static_cast<double>(batch.rays) /
                  static_cast<double>(options.rays);
  }
  return variance;
}

}  // namespace

FitResult fitSpecimen(const Specimen& start, const SpectralDatabase& spectra,
                      const FitTarget& target, const FitOptions& options) {
  // ---- the request ----
  if (options.free.empty()) throw FitError("no quantity to fit (give at least one free quantity)");
  std::vector<FitQuantity> q;
  for (const auto& name : options.free) {
    const FitQuantity& quantity = fitQuantity(name);
    for (const auto& other : q)
      if (other.name == name) throw FitError(fmt::format("fit quantity '{}' is given twice", name));
    q.push_back(quantity);
  }
  const std::size_t n = q.size();
  const std::size_t m = target.wavelengthNm.size();
  if (m == 0)
    throw FitError("the measured curve has no wavelength in common with the fit's wavelengths");
  if (target.reflectance.size() != m)
    throw FitError("measured curve: wavelengths and values differ in number");
  for (std::size_t i = 0; i < m; ++i)
    if (!std::isfinite(target.reflectance[i]) || !std::isfinite(target.wavelengthNm[i]))
      throw FitError(fmt::format("measured curve: value at {} nm is not finite ({})",
                                 target.wavelengthNm[i], target.reflectance[i]));
  if (m < n)
    throw FitError(
        fmt::format("{} free quantities need at least as many wavelengths; the measured curve "
                    "overlaps the fit's wavelengths at {}",
                    n, m));
  if (options.rays == 0) throw FitError("the number of rays must be positive");

  // ---- parameters in [0, 1] over each bound range ----
  std::vector<double> u(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double v = fitQuantityValue(start, q[k].name);
    u[k] = std::clamp((v - q[k].lower) / (q[k].upper - q[k].lower), 0.0, 1.0);
  }
  const auto physical = [&](std::size_t k, double uk) {
    return q[k].lower + uk * (q[k].upper - q[k].lower);
  };
  const auto specimenAt = [&](const std::vector<double>& uu) {
    Specimen s = start;
    for (std::size_t k = 0; k < n; ++k) setFitQuantity(start, s, q[k].name, physical(k, uu[k]));
    return s;
  };
  FitResult result;
  double bestSoFar = std::numeric_limits<double>::infinity();
  const auto residuals = [&](const std::vector<double>& uu,
                             std::vector<Estimate>* model = nullptr) {
    const std::vector<Estimate> r =
        modelReflectance(specimenAt(uu), spectra, target.wavelengthNm, options);
    ++result.evaluations;
    std::vector<double> res(m);
    for (std::size_t i = 0; i < m; ++i) res[i] = r[i].mean - target.reflectance[i];
    bestSoFar = std::min(bestSoFar, std::sqrt(sumSquares(res) / static_cast<double>(m)));
    if (options.progress) options.progress(result.evaluations, bestSoFar);
    if (model) *model = r;
    return res;
  };
  const double h = options.differenceStep;
  const auto jacobian = [&](const std::vector<double>& uu, const std::vector<double>& r0) {
    std::vector<double> jac(m * n);  // row-major: jac[i * n + k]
    for (std::size_t k = 0; k < n; ++k) {
      std::vector<double> up = uu;
      const double step = uu[k] + h <= 1.0 ? h : -h;
      up[k] += step;
      const std::vector<double> r1 = residuals(up);
      for (std::size_t i = 0; i < m; ++i) jac[i * n + k] = (r1[i] - r0[i]) / step;
    }
    return jac;
  };

  std::vector<double> r = residuals(u);
  double cost = sumSquares(r);
  result.startRms = std::sqrt(cost / static_cast<double>(m));
  std::vector<double> jac = jacobian(u, r);
  bool jacobianCurrent = true;
  double lambda = 1e-2;
  result.stopReason = "iteration limit";
  for (result.iterations = 0; result.iterations < options.maxIterations; ++result.iterations) {
    // Gradient and the projected (active-set) system: a quantity at a bound whose gradient
    // pushes it outward stays there.
    std::vector<double> g(n, 0), jtj(n * n, 0);
    for (std::size_t i = 0; i < m; ++i)
      for (std::size_t k = 0; k < n; ++k) {
        g[k] += jac[i * n + k] * r[i];
        for (std::size_t l = 0; l < n; ++l) jtj[k * n + l] += jac[i * n + k] * jac[i * n + l];
      }
    std::vector<std::size_t> freeIdx;
    for (std::size_t k = 0; k < n; ++k)
      if (!((u[k] <= 0 && g[k] > 0) || (u[k] >= 1 && g[k] < 0))) freeIdx.push_back(k);
    if (freeIdx.empty()) {
      result.stopReason = "every quantity at a bound";
      break;
    }
    bool accepted = false;
    double newCost = cost;
    std::vector<double> uNew, rNew;
    for (int attempt = 0; attempt < 8 && !accepted; ++attempt) {
      const std::size_t f = freeIdx.size();
      std::vector<double> a(f * f), b(f), delta;
      double maxDiag = 0;
      for (std::size_t k = 0; k < f; ++k)
        maxDiag = std::max(maxDiag, jtj[freeIdx[k] * n + freeIdx[k]]);
      for (std::size_t k = 0; k < f; ++k) {
        b[k] = -g[freeIdx[k]];
        for (std::size_t l = 0; l < f; ++l) a[k * f + l] = jtj[freeIdx[k] * n + freeIdx[l]];
        a[k * f + k] +=
            lambda * std::max(jtj[freeIdx[k] * n + freeIdx[k]], 1e-9 * maxDiag + 1e-300);
      }
      if (!solveCholesky(a, b, f, delta)) {
        lambda *= 4;
        continue;
      }
      uNew = u;
      double moved = 0;
      for (std::size_t k = 0; k < f; ++k) {
        const std::size_t i = freeIdx[k];
        uNew[i] = std::clamp(u[i] + delta[k], 0.0, 1.0);
        moved = std::max(moved, std::fabs(uNew[i] - u[i]));
      }
      if (moved < 1e-6) {
        lambda *= 4;
        continue;
      }
      rNew = residuals(uNew);
      newCost = sumSquares(rNew);
      if (newCost < cost)
        accepted = true;
      else
        lambda *= 4;
    }
    if (!accepted) {
      result.stopReason = "no step lowers the sum of squares";
      break;
    }
    const double decrease = (cost - newCost) / cost;
    u = uNew;
    r = rNew;
    cost = newCost;
    lambda = std::max(lambda / 3, 1e-7);
    jacobianCurrent = false;
    if (decrease < options.relativeTolerance) {
      result.stopReason = "converged (relative decrease below tolerance)";
      ++result.iterations;
      break;
    }
    jac = jacobian(u, r);
    jacobianCurrent = true;
  }
  if (!jacobianCurrent) jac = jacobian(u, r);

  // ---- result and uncertainties: C = s² (JᵀJ)⁻¹ over the quantities not at a bound ----
  result.specimen = specimenAt(u);
  result.model = modelReflectance(result.specimen, spectra, target.wavelengthNm, options);
  ++result.evaluations;
  result.rms = std::sqrt(cost / static_cast<double>(m));
  std::vector<std::size_t> interior;
  for (std::size_t k = 0; k < n; ++k) {
    FittedQuantity fq;
    fq.quantity = q[k];
    fq.start = fitQuantityValue(start, q[k].name);
    fq.value = physical(k, u[k]);
    fq.atBound = u[k] <= 1e-3 || u[k] >= 1 - 1e-3;
    if (!fq.atBound) interior.push_back(k);
    result.quantities.push_back(fq);
  }
  const std::size_t f = interior.size();
  if (f > 0 && m > f) {
    const double s2 = cost / static_cast<double>(m - f);
    std::vector<double> a(f * f, 0);
    for (std::size_t i = 0; i < m; ++i)
      for (std::size_t k = 0; k < f; ++k)
        for (std::size_t l = 0; l < f; ++l)
          a[k * f + l] += jac[i * n + interior[k]] * jac[i * n + interior[l]];
    // The frozen noise of the model's own curve (the fit's seed) moves the optimum by
    // −(JᵀJ)⁻¹Jᵀδ; its covariance comes from kFitNoiseBatches curves of rays/kFitNoiseBatches
    // rays on other seeds at the optimum: Var(u_k) = Var_b[((JᵀJ)⁻¹Jᵀc_b)_k] / kFitNoiseBatches.
    const std::vector<double> modelNoise = modelNoiseVariance(
        result.specimen, spectra, target.wavelengthNm, options, jac, n, interior, a);
    for (std::size_t k = 0; k < f; ++k) {
      std::vector<double> e(f, 0), col;
      e[k] = 1;
      const std::size_t qk = interior[k];
      const double range = q[qk].upper - q[qk].lower;
      result.quantities[qk].uncertainty =
          solveCholesky(a, e, f, col) && col[k] > 0 && std::isfinite(modelNoise[k])
              ? std::sqrt(s2 * col[k] + modelNoise[k]) * range
              : std::numeric_limits<double>::infinity();
    }
    result.evaluations += 1;  // the batches: one more curve's worth of rays
  }
  return result;
}

}  // namespace hylios::skin
