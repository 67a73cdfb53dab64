// hylios brdf: the angular distribution of light reflected by a specimen — surface (R_s),
// subsurface (R_d) and total (R_t) per exit-direction bin, as BRDF·cos θr (fraction of incident
// rays per steradian, paper Fig. 11) and as BRDF (Fig. 10), for one wavelength or the mean over
// several (--visible: 380–780 nm every 10 nm, equal weight per wavelength — no illuminant
// weighting, since the paper does not name one).
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

#include "app/commands.h"
#include "app/common_options.h"
#include "app/estimator_option.h"
#include "app/gnuplot_plot.h"
#include "app/mpi_session.h"
#include "app/option_checks.h"
#include "app/progress_bar.h"
#include "app/walk_study.h"
#include "app/wavelength_list.h"
#include "skin/core/atomic_file.h"
#include "skin/core/constants.h"
#include "skin/exit_distribution.h"
#include "skin/skin_simulation.h"

namespace hylios {
namespace {

constexpr const char* kVisibleWavelengths = "380:780:10";
constexpr double kDegPerRad = 180.0 / kPi;

struct BrdfArguments {
  WalkStudyOptions study;
  double angleDeg = 45;
  std::string wavelengths;
  bool visible = false;
  std::size_t polarBins = 18;
  std::size_t azimuthBins = 36;
};

std::string formatCsv(const skin::DirectionBins& bins, const skin::ReflectionDistribution& d) {
  std::ostringstream csv;
  csv << "polar_lower_deg,polar_upper_deg,azimuth_lower_deg,azimuth_upper_deg,solid_angle_sr";
  for (const char* quantity : {"per_sr", "brdf"})
    for (const char* part : {"surface", "subsurface", "total"})
      csv << "," << part << "_" << quantity << "," << part << "_" << quantity << "_stderr";
  csv << "\n";
  char buffer[64];
  auto put = [&](double value) {
    std::snprintf(buffer, sizeof buffer, ",%.6g", value);
    csv << buffer;
  };
  auto putEstimate = [&](const skin::Estimate& e) {
    put(e.mean);
    put(e.standardError);
  };
  for (std::size_t i = 0; i < bins.polarBins(); ++i) {
    for (std::size_t j = 0; j < bins.azimuthBins(); ++j) {
      const std::size_t b = bins.flatIndex(i, j);
      std::snprintf(buffer, sizeof buffer, "%.6g", bins.polarLowerRad(i) * kDegPerRad);
      csv << buffer;
      put(bins.polarUpperRad(i) * kDegPerRad);
      put(bins.azimuthLowerRad(j) * kDegPerRad);
      put((bins.azimuthLowerRad(j) + bins.azimuthWidthRad()) * kDegPerRad);
      put(bins.solidAngleSr(i));
      for (const skin::ReflectedDirections* r : {&d.perSteradian, &d.brdf}) {
        putEstimate(r->surface[b]);
        putEstimate(r->subsurface[b]);
        putEstimate(r->total[b]);
      }
      csv << "\n";
    }
  }
  return csv.str();
}

std::string describeWavelengths(const std::vector<double>& wavelengths) {
  std::ostringstream text;
  if (wavelengths.size() == 1) {
    text << wavelengths.front() << " nm";
  } else {
    text << "mean of " << wavelengths.size() << " wavelengths " << wavelengths.front() << "–"
         << wavelengths.back() << " nm (equal weight)";
  }
  return text.str();
}

void plotInPlane(const BrdfArguments& args, const std::string& specimenName,
                 const std::vector<double>& wavelengths, const skin::ReflectionDistribution& d) {
  const skin::InPlaneCut& cut = d.inPlanePerSteradian;
  auto series = [&](const std::string& title, const std::vector<skin::Estimate>& values,
                    const std::string& style) {
    PlotSeries s{title, cut.signedPolarDeg, {}, {}, style};
    for (const skin::Estimate& e : values) {
      s.y.push_back(e.mean);
      s.yError.push_back(e.standardError);
    }
    return s;
  };
  char totals[200];
  std::snprintf(totals, sizeof totals, "R_s = %.4f, R_d = %.4f, R_t = %.4f (± %.1g)",
                d.surfaceReflectance.mean, d.subsurfaceReflectance.mean, d.totalReflectance.mean,
                d.totalReflectance.standardError);
  PlotPanel panel{std::string("in the plane of incidence; ") + totals,
                  "signed reflection angle θr (°): < 0 toward the source, > 0 specular side",
                  "BRDF·cos θr = reflected fraction per sr",
                  false,
                  {series("surface R_s", cut.surface, "linespoints lw 2 pt 7 ps 0.6"),
                   series("subsurface R_d", cut.subsurface, "linespoints lw 2 pt 5 ps 0.6"),
                   series("total R_t", cut.total, "linespoints lw 2 pt 9 ps 0.6")}};
  std::ostringstream title;
  title << "HyLIoS " << specimenName << ", incidence " << args.angleDeg << "°, "
        << describeWavelengths(wavelengths) << ", " << args.study.rays << " rays per wavelength";
  plotPanels(args.study.plot, title.str(), {panel}, 1, 1100, 650);
}

void runBrdf(const BrdfArguments& args) {
  if (args.visible == !args.wavelengths.empty())
    throw std::invalid_argument(
        "hylios brdf: give exactly one of --wavelengths LIST and --visible");
  const WalkStudy study(args.study);
  const skin::Specimen& specimen = study.specimen();
  const std::vector<double> wavelengths =
      parseWavelengthList(args.visible ? kVisibleWavelengths : args.wavelengths);
  const std::vector<skin::SkinOptics> optics = study.optics(wavelengths);
  const skin::DirectionBins bins(args.polarBins, args.azimuthBins);
  skin::WalkRunOptions run = study.run(args.angleDeg);
  run.tally.polarBins = args.polarBins;
  run.tally.azimuthBins = args.azimuthBins;
  std::vector<skin::ReflectionDistribution> perWavelength;
  ProgressBar progress("brdf " + specimen.name, wavelengths.size());
  for (const skin::SkinTally& tally : simulateWithEstimator(args.study.estimator, optics, run))
    perWavelength.push_back(skin::reflectionDistribution(tally));
  progress.advance(wavelengths.size());
  progress.finish();
  if (!MpiSession::isRoot()) return;  // only rank 0 prints and writes
  const skin::ReflectionDistribution d = skin::meanOverWavelengths(perWavelength);
  writeTextAtomically(args.study.out, formatCsv(bins, d));
  std::printf("%s, %s, incidence %g°: R_s = %.5f ± %.5f, R_d = %.5f ± %.5f, R_t = %.5f ± %.5f\n",
              specimen.name.c_str(), describeWavelengths(wavelengths).c_str(), args.angleDeg,
              d.surfaceReflectance.mean, d.surfaceReflectance.standardError,
              d.subsurfaceReflectance.mean, d.subsurfaceReflectance.standardError,
              d.totalReflectance.mean, d.totalReflectance.standardError);
  if (!args.study.plot.empty()) plotInPlane(args, specimen.name, wavelengths, d);
}

}  // namespace

void registerBrdfCommand(CLI::App& app) {
  auto args = std::make_shared<BrdfArguments>();
  args->study.rays = 200000;
  CLI::App* command =
      app.add_subcommand("brdf",
                         "Angular distribution of reflected light: surface/subsurface/total per sr "
                         "and BRDF (CSV, optional in-plane plot)");
  addWalkStudyOptions(*command, args->study, "Rays per wavelength");
  addAngleOption(*command, args->angleDeg);
  auto* wavelengths = command->add_option(
      "--wavelengths", args->wavelengths,
      "start:stop:step or a comma list, nm; several are averaged with equal weight");
  command
      ->add_flag("--visible", args->visible,
                 "Average over 380–780 nm every 10 nm, equal weight per wavelength")
      ->excludes(wavelengths);
  command
      ->add_option("--polar-bins", args->polarBins, "Bins of the reflection angle over [0°, 90°]")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1800}))
      ->capture_default_str();
  command
      ->add_option("--azimuth-bins", args->azimuthBins,
                   "Bins of the azimuth over [−180°, 180°), 0° = specular side")
      ->check(CLI::Range(std::size_t{1}, std::size_t{3600}))
      ->capture_default_str();
  addStudyOutputOptions(*command, args->study,
                        "CSV file to write, one row per (polar, azimuth) bin",
                        "PNG of the in-plane cut (φ = 0° and 180°) to write");
  command->callback([args] { runBrdf(*args); });
}

}  // namespace hylios
