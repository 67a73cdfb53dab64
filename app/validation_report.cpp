#include "app/validation_report.h"

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <numeric>
#include <sstream>

#include "app/gnuplot_plot.h"
#include "app/measured_spectrum.h"
#include "app/population_comparison.h"
#include "renderer/scene/data_paths.h"
#include "skin/core/atomic_file.h"
#include "skin/core/constants.h"
#include "skin/exit_distribution.h"
#include "skin/skin_optics.h"
#include "skin/skin_simulation.h"
#include "skin/specimen.h"
#include "skin/specimen_fit.h"
#include "skin/specimen_writer.h"
#include "skin/spectral_simulation.h"

namespace hylios {
namespace {

std::string fmt(const char* format, double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, v);
  return buffer;
}

std::vector<double> grid(double from, double to, double step) {
  std::vector<double> w;
  for (int i = 0; from + i * step <= to + 1e-9; ++i) w.push_back(from + i * step);
  return w;
}

/// The estimate of an in-plane cut nearest to a signed angle.
skin::Estimate cutAt(const skin::InPlaneCut& cut, const std::vector<skin::Estimate>& values,
                     double signedDeg) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < cut.signedPolarDeg.size(); ++i)
    if (std::fabs(cut.signedPolarDeg[i] - signedDeg) <
        std::fabs(cut.signedPolarDeg[best] - signedDeg))
      best = i;
  return values[best];
}

/// `comparisons` against the group `members` of `nist` at 250–400 nm, sliced from their whole
/// curves (for the UV plot; the report's table holds the whole curves).
std::vector<PopulationComparison> ultravioletSlices(
    const std::vector<PopulationComparison>& comparisons, const SkinPopulation& nist,
    const std::vector<std::size_t>& members) {
  std::vector<PopulationComparison> slices;
  for (const PopulationComparison& c : comparisons) {
    std::vector<double> nm;
    std::vector<skin::Estimate> model;
    for (std::size_t i = 0; i < c.wavelengthNm.size() && c.wavelengthNm[i] <= 400; ++i) {
      nm.push_back(c.wavelengthNm[i]);
      model.push_back(c.model[i]);
    }
    slices.push_back(
        compareWithPopulation(c.specimen, nm, model, c.incidenceDeg, nist, members, c.group));
  }
  return slices;
}

/// Direction bins of the distributions below: 5° polar rings, 10° azimuth bins.
constexpr std::size_t kPolarBins = 18, kAzimuthBins = 36;

/// The per-sr value at the normal: the mean over the first polar ring (0–5°, every azimuth
/// bin, all of which border the normal). The in-plane cut's bins there hold 1/9 of the ring's
/// solid angle, a few dozen rays at 10⁵, and made ratios to them swing by 4× with the seed.
skin::Estimate atNormal(const std::vector<skin::Estimate>& perSteradian) {
  const std::vector<skin::Estimate> ring(perSteradian.begin(), perSteradian.begin() + kAzimuthBins);
  return skin::meanOfIndependent(ring);  // σ ignores the bins' small negative covariance
}

std::string withError(const skin::Estimate& e) {
  return fmt("%.3f", e.mean) + " ± " + fmt("%.3f", e.standardError);
}

skin::ReflectionDistribution distribution(const skin::Specimen& specimen,
                                          const skin::SpectralDatabase& spectra,
                                          const std::vector<double>& wavelengths,
                                          double incidenceDeg, std::uint64_t rays,
                                          std::uint64_t seed) {
  skin::WalkRunOptions run;
  run.incidenceDeg = incidenceDeg;
  run.rays = rays;
  run.seed = seed;
  run.tally.polarBins = kPolarBins;
  run.tally.azimuthBins = kAzimuthBins;
  std::vector<skin::ReflectionDistribution> per;
  for (double w : wavelengths)
    per.push_back(skin::reflectionDistribution(
        skin::simulateSkin(skin::computeSkinOptics(specimen, spectra, w), run)));
  return skin::meanOverWavelengths(per);
}

PlotSeries cutSeries(const std::string& title, const skin::InPlaneCut& cut,
                     const std::vector<skin::Estimate>& values, const std::string& style) {
  PlotSeries s{title, cut.signedPolarDeg, {}, {}, style};
  for (const auto& e : values) {
    s.y.push_back(e.mean);
    s.yError.push_back(2 * e.standardError);
  }
  return s;
}

/// Two panels of in-plane cuts (surface, subsurface, total per sr ± 2σ), one per distribution,
/// side by side in one PNG; `names` are the three series' names.
void plotInPlaneCuts(const std::filesystem::path& png, const std::string& title,
                     const std::array<const skin::ReflectionDistribution*, 2>& distributions,
                     const std::array<std::string, 2>& panelTitles, const std::string& yLabel,
                     const std::array<std::string, 3>& names) {
  std::vector<PlotPanel> panels;
  for (std::size_t i = 0; i < 2; ++i) {
    const skin::InPlaneCut& c = distributions[i]->inPlanePerSteradian;
    panels.push_back({panelTitles[i],
                      "signed reflection angle (°): < 0 toward the source",
                      yLabel,
                      false,
                      {cutSeries(names[0] + " ± 2σ", c, c.surface, "lines lw 1 dt 2"),
                       cutSeries(names[1] + " ± 2σ", c, c.subsurface, "lines lw 1 dt 3"),
                       cutSeries(names[2] + " ± 2σ", c, c.total, "linespoints lw 2 pt 7 ps 0.5")}});
  }
  plotPanels(png, title, panels, 2, 1400, 600);
}

struct Check {
  std::string figure, quantity, model, reference, verdict;
};

std::string checkMark(bool ok) { return ok ? "consistent" : "**not consistent**"; }

double seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

}  // namespace

std::vector<skin::Estimate> modelReflectanceCurve(const skin::Specimen& specimen,
                                                  const std::vector<double>& wavelengths,
                                                  double incidenceDeg, std::uint64_t rays,
                                                  std::uint64_t seed,
                                                  const skin::SpectralDatabase& spectra) {
  std::vector<skin::SkinOptics> optics;
  for (double w : wavelengths) optics.push_back(skin::computeSkinOptics(specimen, spectra, w));
  skin::SpectralRunOptions run;
  run.incidenceDeg = incidenceDeg;
  run.rays = rays;
  run.seed = seed;
  run.walk.layerAbsorption = false;
  run.splitRayleighWithoutDeflection = true;  // a scalar curve (skin/spectral_simulation.h)
  std::vector<skin::Estimate> curve;
  for (const auto& t : skin::simulateSkinSpectral(optics, run)) curve.push_back(t.reflectance());
  return curve;
}

CurveComparison compareWithMeasured(const std::string& specimenName,
                                    const std::filesystem::path& ncsuFile,
                                    const std::string& column,
                                    const std::vector<double>& wavelengths, double incidenceDeg,
                                    std::uint64_t rays, std::uint64_t seed,
                                    const skin::SpectralDatabase& spectra) {
  const MeasuredSpectrum measured = loadMeasuredSpectrum(ncsuFile.string() + ":" + column);
  const skin::Specimen specimen = skin::loadSpecimen(specimenName, specimenDir());
  CurveComparison c;
  c.specimen = specimen.name;
  c.measuredLabel = measured.label;
  c.measuredColumn = column;
  c.incidenceDeg = incidenceDeg;
  for (double w : wavelengths)
    if (measured.covers(w)) {
      c.wavelengthNm.push_back(w);
      c.measured.push_back(measured.at(w));
    }
  if (c.wavelengthNm.empty())
    throw std::runtime_error("measured curve " + column + " covers none of the wavelengths");
  c.model = modelReflectanceCurve(specimen, c.wavelengthNm, incidenceDeg, rays, seed, spectra);
  double sum2 = 0, sumE = 0, noise2 = 0;
  for (std::size_t i = 0; i < c.model.size(); ++i) {
    const double e = c.model[i].mean - c.measured[i];
    sum2 += e * e;
    sumE += e;
    noise2 += c.model[i].standardError * c.model[i].standardError;
    if (std::fabs(e) > c.maxAbsError) {
      c.maxAbsError = std::fabs(e);
      c.worstWavelengthNm = c.wavelengthNm[i];
    }
  }
  const double m = static_cast<double>(c.model.size());
  c.rms = std::sqrt(sum2 / m);
  c.meanError = sumE / m;
  c.noiseRms = std::sqrt(noise2 / m);
  return c;
}

std::string runValidation(const ValidationOptions& options) {
  const std::filesystem::path images = options.outDir / "validation";
  std::filesystem::create_directories(images);
  const auto spectra = skin::SpectralDatabase::load(spectraDir());
  const std::filesystem::path ncsu =
      dataRoot() / "tests" / "data" / "validation" / "ncsu_vrhel1994_skin.csv";
  const std::uint64_t rays = options.rays, seed = options.seed;
  std::vector<Check> checks;

  // ---- Fig. 7: NCSU ----
  auto t0 = std::chrono::steady_clock::now();
  const std::vector<double> visible = grid(400, 700, 10);
  const std::vector<CurveComparison> curves = {
      compareWithMeasured("S1", ncsu, "obj117", visible, 45, rays, seed, spectra),
      compareWithMeasured("S2", ncsu, "obj113", visible, 45, rays, seed, spectra)};
  std::cout << "validate: Fig. 7 (NCSU) " << fmt("%.1f", seconds(t0)) << " s\n";
  if (options.plots) {
    std::vector<PlotPanel> panels;
    for (const auto& c : curves) {
      PlotSeries model{"HyLIoS " + c.specimen + " ± 2σ", c.wavelengthNm, {}, {}, "lines lw 2"};
      for (const auto& e : c.model) {
        model.y.push_back(e.mean);
        model.yError.push_back(2 * e.standardError);
      }
      PlotSeries meas{"measured NCSU " + c.measuredLabel,
                      c.wavelengthNm,
                      c.measured,
                      {},
                      "linespoints lw 2 pt 7 ps 0.6 lc rgb 'black'"};
      panels.push_back({c.specimen + " vs " + c.measuredColumn + ": RMS " + fmt("%.4f", c.rms),
                        "wavelength (nm)",
                        "reflectance (45° incidence)",
                        false,
                        {model, meas}});
    }
    plotPanels(images / "fig7_ncsu.png", "Paper Fig. 7: HyLIoS vs NCSU skin (Vrhel et al. 1994)",
               panels, 2, 1400, 600);
  }

  // ---- Fig. 9: S3 and S4 against the NIST population, 250–2500 nm ----
  t0 = std::chrono::steady_clock::now();
  const SkinPopulation nist = loadSkinPopulation(dataRoot() / "tests" / "data" / "validation" /
                                                 "nist_cooksey2017_skin.csv");
  const std::vector<double> wholeRange = grid(250, 2500, 10);
  std::vector<std::size_t> everyone(nist.subjects.size());
  std::iota(everyone.begin(), everyone.end(), std::size_t{0});
  std::vector<PopulationComparison> population;
  for (const auto& [name, lightest] : {std::pair{"S3", true}, std::pair{"S4", false}}) {
    const skin::Specimen specimen = skin::loadSpecimen(name, specimenDir());
    const auto model = modelReflectanceCurve(specimen, wholeRange, 8, rays, seed, spectra);
    population.push_back(compareWithPopulation(
        specimen.name, wholeRange, model, 8, nist, nist.quantileGroup(0.25, lightest),
        lightest ? "NIST lightest quarter" : "NIST darkest quarter"));
    population.push_back(compareWithPopulation(specimen.name, wholeRange, model, 8, nist, everyone,
                                               "all NIST subjects"));
  }
  // The paper's other lightly pigmented specimens, and S3 with the measured site's stratum corneum.
  const std::vector<std::size_t> lightestQuarter = nist.quantileGroup(0.25, true);
  const auto againstTheLightestQuarter = [&](const skin::Specimen& specimen,
                                             const std::string& label) {
    return compareWithPopulation(
        label, wholeRange, modelReflectanceCurve(specimen, wholeRange, 8, rays, seed, spectra), 8,
        nist, lightestQuarter, "NIST lightest quarter");
  };
  skin::Specimen s3AtTheSite = skin::loadSpecimen("S3", specimenDir());
  const double stratumCorneumMuAt300Nm =
      skin::computeSkinOptics(s3AtTheSite, spectra, 300)[skin::Layer::StratumCorneum]
          .muATotal_perCm;
  s3AtTheSite.thicknessCm[skin::index(skin::Layer::StratumCorneum)] = kNistSiteStratumCorneumCm;
  const std::vector<PopulationComparison> light = {
      population[0], againstTheLightestQuarter(skin::loadSpecimen("S1", specimenDir()), "S1"),
      againstTheLightestQuarter(skin::loadSpecimen("S2", specimenDir()), "S2"),
      againstTheLightestQuarter(
          s3AtTheSite,
          "S3, stratum corneum " + fmt("%.0f", kNistSiteStratumCorneumCm * 1e4) + " µm")};
  population.insert(population.end(), light.begin() + 1, light.end());
  std::cout << "validate: Fig. 9 (NIST population) " << fmt("%.1f", seconds(t0)) << " s\n";
  if (options.plots) {
    plotPopulationComparisons(images / "fig9_nist.png",
                              "Paper Fig. 9: HyLIoS S3 and S4 vs the NIST skin reflectance set "
                              "(Cooksey et al. 2017), 8° incidence",
                              {population[0], population[2]});
    plotPopulationComparisons(images / "fig9_nist_uv.png",
                              "Lightly pigmented specimens vs the NIST set's lightest quarter, "
                              "250-400 nm, 8° incidence",
                              ultravioletSlices(light, nist, lightestQuarter));
  }

  // ---- Fig. 8: S2 epidermis at 302 nm ----
  t0 = std::chrono::steady_clock::now();
  const skin::Specimen s2 = skin::loadSpecimen("S2", specimenDir());
  const skin::SkinOptics optics302 = skin::computeSkinOptics(s2, spectra, 302);
  skin::WalkRunOptions epi;
  epi.rays = rays;
  epi.seed = seed;
  epi.walk.deepestLayer = skin::Layer::StratumBasale;
  epi.walk.belowRefractiveIndex = optics302[skin::Layer::StratumBasale].refractiveIndex;
  epi.tally.polarBins = kPolarBins;
  epi.tally.azimuthBins = 1;
  const skin::TransmissionProfile profile =
      skin::transmissionProfile(skin::simulateSkin(optics302, epi));
  double hwhm = 90;
  for (std::size_t i = 1; i < profile.relativeToNormal.size(); ++i) {
    const double a = profile.relativeToNormal[i - 1].mean, b = profile.relativeToNormal[i].mean;
    if (b < 0.5 && a >= 0.5) {
      const double ca = 0.5 * (profile.polarLowerDeg[i - 1] + profile.polarUpperDeg[i - 1]);
      const double cb = 0.5 * (profile.polarLowerDeg[i] + profile.polarUpperDeg[i]);
      hwhm = ca + (a - 0.5) / (a - b) * (cb - ca);
      break;
    }
  }
  const auto relAt = [&](double deg) {
    for (std::size_t i = 0; i < profile.polarLowerDeg.size(); ++i)
      if (deg >= profile.polarLowerDeg[i] && deg < profile.polarUpperDeg[i])
        return profile.relativeToNormal[i];
    return skin::Estimate{};
  };
  const skin::Estimate rel30 = relAt(32.5), rel60 = relAt(62.5);
  checks.push_back(
      {"8", "half width at half maximum of the transmitted intensity per sr", fmt("%.1f°", hwhm),
       "60° for a diffuse (cos θ) profile; BVDL84: strongly forward", checkMark(hwhm < 60)});
  checks.push_back({"8", "intensity per sr at 30–35° / at the normal",
                    fmt("%.3f", rel30.mean) + " ± " + fmt("%.3f", rel30.standardError),
                    "cos 32.5° = 0.843 (diffuse)",
                    checkMark(rel30.mean < std::cos(32.5 * kPi / 180))});
  checks.push_back({"8", "intensity per sr at 60–65° / at the normal",
                    fmt("%.3f", rel60.mean) + " ± " + fmt("%.3f", rel60.standardError),
                    "cos 62.5° = 0.462 (diffuse)",
                    checkMark(rel60.mean < std::cos(62.5 * kPi / 180))});
  checks.push_back({"8", "epidermis transmittance at 302 nm",
                    fmt("%.4f", profile.transmittance.mean) + " ± " +
                        fmt("%.4f", profile.transmittance.standardError),
                    "no measured value in the project", "—"});
  std::cout << "validate: Fig. 8 (302 nm epidermis) " << fmt("%.1f", seconds(t0)) << " s\n";
  if (options.plots) {
    PlotSeries model{"HyLIoS S2 epidermis ± 2σ", {}, {}, {}, "linespoints lw 2 pt 7 ps 0.6"};
    PlotSeries diffuse{"cos θ (diffuse)", {}, {}, {}, "lines lw 1 dt 2 lc rgb 'black'"};
    for (std::size_t i = 0; i < profile.relativeToNormal.size(); ++i) {
      model.x.push_back(0.5 * (profile.polarLowerDeg[i] + profile.polarUpperDeg[i]));
      model.y.push_back(profile.relativeToNormal[i].mean);
      model.yError.push_back(2 * profile.relativeToNormal[i].standardError);
    }
    for (int d = 0; d <= 90; ++d) {
      diffuse.x.push_back(d);
      diffuse.y.push_back(std::cos(d * kPi / 180));
    }
    plotPanels(images / "fig8_forward_profile.png",
               "Paper Fig. 8: light transmitted through the S2 epidermis, 302 nm, normal incidence "
               "(no measured data in the project)",
               {{"",
                 "angle from the inward normal (°)",
                 "intensity per sr / at the normal",
                 false,
                 {model, diffuse}}},
               1, 1000, 600);
  }

  // ---- Fig. 10: S1 visible BRDF at 0° and 60° ----
  t0 = std::chrono::steady_clock::now();
  const skin::Specimen s1 = skin::loadSpecimen("S1", specimenDir());
  const std::vector<double> band = grid(380, 780, 20);
  const std::uint64_t bandRays = std::max<std::uint64_t>(1000, rays / 5);
  const skin::ReflectionDistribution at0 = distribution(s1, spectra, band, 0, bandRays, seed);
  const skin::ReflectionDistribution at60 = distribution(s1, spectra, band, 60, bandRays, seed);
  {
    const auto& c = at0.inPlanePerSteradian;
    const skin::Estimate normal = atNormal(at0.perSteradian.total);
    const skin::Estimate grazing =
        skin::meanOfIndependent({cutAt(c, c.subsurface, 62.5), cutAt(c, c.subsurface, -62.5)});
    const skin::Estimate ratio =
        skin::ratioOfIndependent(grazing, atNormal(at0.perSteradian.subsurface));
    const skin::Estimate left = cutAt(c, c.total, -42.5), right = cutAt(c, c.total, 42.5);
    const skin::Estimate asym = skin::ratioOfIndependent(
        {std::fabs(right.mean - left.mean), std::hypot(right.standardError, left.standardError)},
        normal);
    checks.push_back(
        {"10", "0° incidence: subsurface per sr at ±62.5° / at the normal (± σ)", withError(ratio),
         "cos 62.5° = 0.462 for a Lambertian reflector (MWL99: near-Lambertian); exit Fresnel "
         "transmission lowers it at grazing angles",
         "— (shape only, no data)"});
    checks.push_back(
        {"10", "0° incidence: \\|left − right\\| of the total at ±42.5° / at the normal (± σ)",
         withError(asym), "0 (symmetric)", checkMark(asym.mean < 0.05)});
    const auto& d = at60.inPlanePerSteradian;
    const skin::Estimate forwardOverBack =
        skin::ratioOfIndependent(cutAt(d, d.total, 62.5), cutAt(d, d.total, -62.5));
    checks.push_back({"10",
                      "60° incidence: total per sr at +62.5° (specular side) / at −62.5° (± σ)",
                      withError(forwardOverBack), "> 1: forward (specular) lobe, MWL99",
                      checkMark(forwardOverBack.mean > 1)});
    checks.push_back(
        {"10", "visible total reflectance R_t at 0° / 60°",
         fmt("%.4f", at0.totalReflectance.mean) + " / " + fmt("%.4f", at60.totalReflectance.mean),
         "no measured value in the project", "—"});
  }
  std::cout << "validate: Fig. 10 (visible BRDF) " << fmt("%.1f", seconds(t0)) << " s\n";
  if (options.plots)
    plotInPlaneCuts(images / "fig10_brdf.png",
                    "Paper Fig. 10: S1 visible BRDF in the plane of incidence (no measured data in "
                    "the project)",
                    {&at0, &at60}, {"incidence 0°", "incidence 60°"},
                    "BRDF·cos θr (per sr), 380–780 nm mean", {"surface", "subsurface", "total"});

  // ---- Fig. 11: S1 at 45°, 365 vs 1100 nm ----
  t0 = std::chrono::steady_clock::now();
  const skin::ReflectionDistribution uv = distribution(s1, spectra, {365}, 45, rays, seed);
  const skin::ReflectionDistribution ir = distribution(s1, spectra, {1100}, 45, rays, seed);
  {
    const double dUv = uv.subsurfaceReflectance.mean / uv.totalReflectance.mean;
    const double dIr = ir.subsurfaceReflectance.mean / ir.totalReflectance.mean;
    checks.push_back({"11", "subsurface share R_d/R_t at 365 nm / 1100 nm",
                      fmt("%.3f", dUv) + " / " + fmt("%.3f", dIr),
                      "IR more diffuse than UV [AP82, HASS10]", checkMark(dIr > dUv)});
    const auto peak = [](const skin::ReflectionDistribution& d) {
      skin::Estimate p;
      for (const auto& e : d.inPlanePerSteradian.total)
        if (e.mean > p.mean) p = e;
      return skin::ratioOfIndependent(p, atNormal(d.perSteradian.total));
    };
    const skin::Estimate pUv = peak(uv), pIr = peak(ir);
    checks.push_back({"11", "peak / normal of the in-plane total per sr at 365 nm / 1100 nm (± σ)",
                      withError(pUv) + " / " + withError(pIr), "lower in the IR (more diffuse)",
                      checkMark(pIr.mean < pUv.mean)});
  }
  std::cout << "validate: Fig. 11 (365 / 1100 nm) " << fmt("%.1f", seconds(t0)) << " s\n";
  if (options.plots)
    plotInPlaneCuts(
        images / "fig11_uv_ir.png",
        "Paper Fig. 11: S1 at 45°, UV vs IR in the plane of incidence (no measured data "
        "in the project)",
        {&uv, &ir}, {"365 nm", "1100 nm"}, "BRDF·cos θr (per sr)", {"R_s", "R_d", "R_t"});

  // ---- S2 fitted to object 113 (hylios fit), next to Table 1 ----
  t0 = std::chrono::steady_clock::now();
  skin::FitResult fit;
  {
    const MeasuredSpectrum obj113 = loadMeasuredSpectrum(ncsu.string() + ":obj113");
    skin::FitTarget target;
    for (double w : visible) {
      target.wavelengthNm.push_back(w);
      target.reflectance.push_back(obj113.at(w));
    }
    skin::FitOptions fitOptions;
    fitOptions.free = {"melanosome", "colloidal", "blood", "oxygenation", "water_reduction"};
    fitOptions.rays = std::max<std::uint64_t>(1000, rays / 5);
    fitOptions.seed = seed;
    fit = skin::fitSpecimen(s2, spectra, target, fitOptions);
  }
  const CurveComparison fitted = [&] {
    // The fitted specimen evaluated like the Table 1 ones (exact melanosomes, another seed).
    const std::filesystem::path tmp = images / "S2_fitted_obj113.toml";
    writeTextAtomically(
        tmp, skin::formatSpecimenToml(fit.specimen, "S2 fitted to NCSU obj113 by hylios validate"));
    CurveComparison c =
        compareWithMeasured(tmp.string(), ncsu, "obj113", visible, 45, rays, seed + 1, spectra);
    return c;
  }();
  std::cout << "validate: S2 fit to obj113 " << fmt("%.1f", seconds(t0)) << " s\n";

  // ---- the report ----
  std::ostringstream md;
  md << "# Validation against measured skin\n\n"
     << "Written by `hylios validate --rays " << rays << " --seed " << seed
     << "` (issue 14); this file is its output. Monte Carlo errors (σ) are the walk's standard "
        "errors; bands in the "
        "plots are ±2σ. Rerun it after any model change.\n\n"
     << "## Measured curves\n\n"
     << "| comparison | data | wavelengths | RMS | max \\|error\\| | worst at | mean error (model "
        "− measured) | MC σ of the RMS |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  for (const auto& c : curves)
    md << "| " << c.specimen << " vs NCSU " << c.measuredColumn << ", " << c.incidenceDeg
       << "° (Fig. 7) | Vrhel et al. 1994, `" << c.measuredLabel << "` | " << c.wavelengthNm.front()
       << "–" << c.wavelengthNm.back() << " nm, " << c.wavelengthNm.size() << " | "
       << fmt("%.4f", c.rms) << " | " << fmt("%.4f", c.maxAbsError) << " | " << c.worstWavelengthNm
       << " nm | " << fmt("%+.4f", c.meanError) << " | ≤ " << fmt("%.4f", c.noiseRms) << " |\n";
  md << "| S2 fitted to obj113 (`hylios fit`, below), 45° | same | 400–700 nm, "
     << fitted.wavelengthNm.size() << " | " << fmt("%.4f", fitted.rms) << " | "
     << fmt("%.4f", fitted.maxAbsError) << " | " << fitted.worstWavelengthNm << " nm | "
     << fmt("%+.4f", fitted.meanError) << " | ≤ " << fmt("%.4f", fitted.noiseRms) << " |\n";
  md << "\nModel: spectral walk (exact melanosomes), " << rays
     << " rays per wavelength. The project's goal is RMS ≤ 0.03 for each. `hylios fit` fits "
        "specimen quantities to "
        "these curves (README).\n\n![Fig. 7](validation/fig7_ncsu.png)\n\n";
  md << "## A measured population, UV to IR (Fig. 9)\n\n"
     << "The NIST reference set (Cooksey, Allen & Tsai 2017: 100 subjects, 250–2500 nm, "
        "directional-hemispherical reflectance factor) ranked by mean reflectance over 500–700 nm. "
        "The paper's Fig. 9 compares S3 with a lightly pigmented specimen of Cooksey & Allen 2013 "
        "at 8° and S4 with a darkly pigmented one of Jacquez et al. 1955 at 16.75°; the project "
        "holds neither, so S3 is set against the set's lightest quarter and S4 against its darkest "
        "quarter (the darkest the set holds: mean 500–700 nm reflectance "
     << fmt("%.2f", nist.lightness(nist.byLightness().back())) << " to "
     << fmt("%.2f", nist.lightness(nist.quantileGroup(0.25, false).back())) << "), both at 8°. "
     << "Each region's cell: the wavelengths where the model lies inside the group's measured "
        "range "
        "(within 2σ of the model), and the largest excess beyond it (model − nearest edge) and "
        "where.\n\n"
     << populationTable(population) << "\n![Fig. 9](validation/fig9_nist.png)\n\n"
     << "The last three rows hold the UV goal of issue 14 (lightly pigmented skin inside the "
        "measured range at 250–310 nm). S1 and S2 are the paper's other lightly pigmented "
        "specimens, with Table 1's own values. The last row is S3 with the stratum corneum of "
        "the site the NIST set measured, the inside of the forearm: "
     << fmt("%.0f", kNistSiteStratumCorneumCm * 1e4)
     << " µm, inside the 17.6–22.6 µm measured there in vivo by confocal Raman (Egawa, Hirao & "
        "Takahashi, Acta Derm. Venereol. 87, 4, 2007; Skin Res. Technol. 24, 504, 2018). "
        "Table 1 gives S3 4 µm, S1 and S2 10 µm. At 300 nm the stratum corneum absorbs "
     << fmt("%.0f", stratumCorneumMuAt300Nm)
     << " cm⁻¹ (urocanic acid and keratin), and the light crosses it twice; where the rest "
        "of S3's UV light turns back is in docs/uv-absorbers.md.\n\n"
     << "![Fig. 9, UV](validation/fig9_nist_uv.png)\n\n";
  md << "## S2 fitted to NCSU object 113, next to Table 1\n\n"
     << "`hylios fit` (bounded Levenberg–Marquardt, common random numbers; bounds and sources in "
        "docs/interpretations.md) with 5 free quantities, "
     << std::max<std::uint64_t>(1000, rays / 5) << " rays per wavelength and evaluation: RMS "
     << fmt("%.4f", fit.startRms) << " → " << fmt("%.4f", fit.rms) << " in " << fit.evaluations
     << " curve evaluations (" << fit.stopReason
     << "). The fitted specimen re-evaluated with the exact walk and "
        "another seed is the last row of the table above; it is written to "
        "`validation/S2_fitted_obj113.toml`.\n\n"
     << "| quantity | Table 1 (S2) | fitted ± 1σ | bounds |\n|---|---|---|---|\n";
  for (const auto& q : fit.quantities)
    md << "| " << q.quantity.name << " | " << fmt("%.4g", q.start) << " " << q.quantity.unit
       << " | " << fmt("%.4g", q.value) << " " << q.quantity.unit
       << (q.atBound ? " (at a bound)"
           : q.uncertainty > q.quantity.upper - q.quantity.lower
               ? " (unconstrained: σ exceeds the bound range)"
               : " ± " + fmt("%.2g", q.uncertainty) + " " + q.quantity.unit)
       << " | " << fmt("%g", q.quantity.lower) << "–" << fmt("%g", q.quantity.upper) << " "
       << q.quantity.unit << " |\n";
  md << "\nA fit explains the curve with the freed quantities; it does not say the model's other "
        "choices are "
        "right. Water reduction is barely constrained by 400–700 nm: it ends at a bound or with a "
        "σ wider than its range. Melanosome and colloidal melanin trade against each other (both "
        "are melanin), so their σ are large and their split moves with the seed and ray count.\n\n";
  md << "## Angular distributions (no measured data in the project)\n\n"
     << "The project holds no digitised data of Bruls & van der Leun 1984 (Fig. 8) or Marschner et "
        "al. 1999 "
        "(Fig. 10), and Fig. 11 has no measurement. The rows check the behaviour the paper states "
        "for them.\n\n"
     << "| Fig. | quantity | model | reference | verdict |\n|---|---|---|---|---|\n";
  for (const auto& c : checks)
    md << "| " << c.figure << " | " << c.quantity << " | " << c.model << " | " << c.reference
       << " | " << c.verdict << " |\n";
  md << "\nFig. 8: S2 epidermis (stratum corneum to basale), bottom index matched, " << rays
     << " rays. Fig. 10: S1, mean of 380–780 nm every 20 nm, " << bandRays
     << " rays per wavelength. Fig. 11: S1, 45°, " << rays
     << " rays. \"At the normal\" is the mean per sr over the polar ring 0–5° (every "
        "azimuth); σ of a ratio is first order, its two estimates taken as independent.\n\n"
     << "![Fig. 8](validation/fig8_forward_profile.png)\n\n![Fig. "
        "10](validation/fig10_brdf.png)\n\n![Fig. 11](validation/fig11_uv_ir.png)\n";
  const std::string text = md.str();
  writeTextAtomically(options.outDir / "validation.md", text);
  return text;
}

}  // namespace hylios
