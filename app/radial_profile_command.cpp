// hylios radial-profile: R(r), the subsurface reflectance per unit area at distance r from the
// entry point (the radially symmetric part of the BSSRDF), in cm⁻²: the fraction of incident
// rays leaving through the surface within an annulus divided by its area π(r2² − r1²).

#include <cstdio>
#include <memory>
#include <sstream>

#include "app/commands.h"
#include "app/common_options.h"
#include "app/estimator_option.h"
#include "app/gnuplot_plot.h"
#include "app/mpi_session.h"
#include "app/option_checks.h"
#include "app/walk_study.h"
#include "skin/core/atomic_file.h"
#include "skin/exit_distribution.h"
#include "skin/skin_simulation.h"

namespace hylios {
namespace {

/// --max-radius-cm: below 1 µm the annuli's areas underflow; above 1 m no light comes back.
constexpr double kMinMaxRadiusCm = 1e-4;
constexpr double kMaxMaxRadiusCm = 100;

struct RadialProfileArguments {
  WalkStudyOptions study;
  double wavelengthNm = 550;
  double angleDeg = 0;
  double maxRadiusCm = 0.5;
  std::size_t bins = 100;
};

std::string formatCsv(const skin::RadialProfile& p) {
  std::ostringstream csv;
  csv << "inner_radius_cm,outer_radius_cm,annulus_area_cm2,fraction,fraction_stderr,"
         "reflectance_per_cm2,reflectance_per_cm2_stderr\n";
  char line[256];
  for (std::size_t i = 0; i < p.perCm2.size(); ++i) {
    std::snprintf(line, sizeof line, "%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", p.innerCm[i],
                  p.outerCm[i], skin::annulusAreaCm2(p.innerCm[i], p.outerCm[i]),
                  p.fraction[i].mean, p.fraction[i].standardError, p.perCm2[i].mean,
                  p.perCm2[i].standardError);
    csv << line;
  }
  return csv.str();
}

void plotProfile(const RadialProfileArguments& args, const std::string& specimenName,
                 const skin::RadialProfile& p) {
  PlotSeries profile{"subsurface R(r) ± 1 s.e.", {}, {}, {}, "linespoints lw 2 pt 7 ps 0.5"};
  for (std::size_t i = 0; i < p.perCm2.size(); ++i) {
    if (!(p.perCm2[i].mean > 0))
      continue;  // no exit in this annulus: nothing to draw on a log axis
    profile.x.push_back(0.5 * (p.innerCm[i] + p.outerCm[i]));
    profile.y.push_back(p.perCm2[i].mean);
    profile.yError.push_back(p.perCm2[i].standardError);
  }
  char title[300];
  std::snprintf(title, sizeof title,
                "HyLIoS %s, %g nm, incidence %g°, %llu rays: R_d = %.4f ± %.4f (%.4f beyond %g cm)",
                specimenName.c_str(), args.wavelengthNm, args.angleDeg,
                static_cast<unsigned long long>(args.study.rays), p.subsurfaceReflectance.mean,
                p.subsurfaceReflectance.standardError, p.beyondMaxRadius.mean, args.maxRadiusCm);
  PlotPanel panel{"subsurface reflectance per unit area around the entry point",
                  "distance from the entry point r (cm)",
                  "R(r) (cm^{-2})",
                  true,
                  {profile}};
  plotPanels(args.study.plot, title, {panel}, 1, 1000, 650);
}

void runRadialProfile(const RadialProfileArguments& args) {
  const WalkStudy study(args.study);
  const skin::Specimen& specimen = study.specimen();
  const skin::SkinOptics optics = study.optics(args.wavelengthNm);
  skin::WalkRunOptions run = study.run(args.angleDeg);
  run.tally.radialBins = args.bins;
  run.tally.maxRadiusCm = args.maxRadiusCm;
  const skin::RadialProfile profile =
      skin::radialProfile(simulateWithEstimator(args.study.estimator, {optics}, run).front());
  if (!MpiSession::isRoot()) return;  // only rank 0 prints and writes
  writeTextAtomically(args.study.out, formatCsv(profile));
  std::printf("%s at %g nm, incidence %g°: R_d = %.5f ± %.5f, of which %.5f ± %.5f beyond %g cm\n",
              specimen.name.c_str(), args.wavelengthNm, args.angleDeg,
              profile.subsurfaceReflectance.mean, profile.subsurfaceReflectance.standardError,
              profile.beyondMaxRadius.mean, profile.beyondMaxRadius.standardError,
              args.maxRadiusCm);
  if (!args.study.plot.empty()) plotProfile(args, specimen.name, profile);
}

}  // namespace

void registerRadialProfileCommand(CLI::App& app) {
  auto args = std::make_shared<RadialProfileArguments>();
  args->study.rays = 1000000;
  CLI::App* command = app.add_subcommand("radial-profile",
                                         "Subsurface reflectance per unit area vs distance from "
                                         "the entry point, R(r) in cm⁻² (BSSRDF)");
  addWalkStudyOptions(*command, args->study, "Rays");
  addWavelengthOption(*command, args->wavelengthNm);
  addAngleOption(*command, args->angleDeg);
  command
      ->add_option("--max-radius-cm", args->maxRadiusCm,
                   "Outer radius of the last annulus, cm, in [1e-4, 100] (1 µm to 1 m)")
      ->check(finiteRange(kMinMaxRadiusCm, kMaxMaxRadiusCm))
      ->capture_default_str();
  command->add_option("--bins", args->bins, "Annuli of equal width over [0, max radius)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{100000}))
      ->capture_default_str();
  addStudyOutputOptions(*command, args->study, "CSV file to write, one row per annulus",
                        "PNG plot (log R) to write");
  command->callback([args] { runRadialProfile(*args); });
}

}  // namespace hylios
