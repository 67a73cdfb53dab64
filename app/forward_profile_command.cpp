// hylios forward-profile: the forward scattering of the epidermis (paper Fig. 8, after Bruls and
// van der Leun 1984). Only stratum corneum to stratum basale are simulated; light arrives along
// the normal and leaves through the smooth bottom of the stratum basale into a medium of index
// --below-index: "matched" (default) = the stratum basale's own index at that wavelength, so that
// the bottom neither refracts nor reflects and the profile is the epidermis's own scattering; a
// number (e.g. 1.0 for air) adds that interface's refraction and total internal reflection.
// Output: per polar bin (angle from the inward normal, azimuths merged) the transmitted fraction
// per steradian, and the same normalised to the bin at 0° as in the paper's plot.

#include <cmath>
#include <cstdio>
#include <cstdlib>
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
#include "skin/core/constants.h"
#include "skin/exit_distribution.h"
#include "skin/skin_simulation.h"

namespace hylios {
namespace {

constexpr double kRadPerDeg = kPi / 180.0;

struct ForwardProfileArguments {
  WalkStudyOptions study;
  double wavelengthNm = 302;
  std::size_t polarBins = 18;
  std::string belowIndex = "matched";
};

/// The index below the stratum basale: "matched" or a finite number ≥ 1.
double belowRefractiveIndex(const std::string& text, const skin::SkinOptics& optics) {
  if (text == "matched") return optics[skin::Layer::StratumBasale].refractiveIndex;
  char* end = nullptr;
  const double n = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(n) || n < 1.0 || n > 10.0)
    throw std::invalid_argument("--below-index '" + text +
                                "': expected 'matched' or a refractive index in [1, 10]");
  return n;
}

std::string formatCsv(const skin::TransmissionProfile& p) {
  std::ostringstream csv;
  csv << "polar_lower_deg,polar_upper_deg,solid_angle_sr,transmitted_per_sr,transmitted_per_sr_"
         "stderr,"
         "relative_to_normal,relative_to_normal_stderr\n";
  char line[256];
  for (std::size_t i = 0; i < p.perSteradian.size(); ++i) {
    std::snprintf(line, sizeof line, "%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", p.polarLowerDeg[i],
                  p.polarUpperDeg[i], p.solidAngleSr[i], p.perSteradian[i].mean,
                  p.perSteradian[i].standardError, p.relativeToNormal[i].mean,
                  p.relativeToNormal[i].standardError);
    csv << line;
  }
  return csv.str();
}

void plotProfile(const ForwardProfileArguments& args, const std::string& specimenName,
                 double belowIndex, const skin::TransmissionProfile& p) {
  PlotSeries model{"HyLIoS ± 1 s.e.", {}, {}, {}, "linespoints lw 2 pt 7 ps 0.6"};
  PlotSeries diffuse{"cos θ (diffuse)", {}, {}, {}, "lines lw 1 dt 2 lc rgb 'black'"};
  for (std::size_t i = 0; i < p.perSteradian.size(); ++i) {
    const double centreDeg = 0.5 * (p.polarLowerDeg[i] + p.polarUpperDeg[i]);
    model.x.push_back(centreDeg);
    model.y.push_back(p.relativeToNormal[i].mean);
    model.yError.push_back(p.relativeToNormal[i].standardError);
  }
  for (int deg = 0; deg <= 90; ++deg) {
    diffuse.x.push_back(deg);
    diffuse.y.push_back(std::cos(deg * kRadPerDeg));
  }
  char title[300];
  std::snprintf(
      title, sizeof title,
      "HyLIoS %s epidermis, %g nm, normal incidence, %llu rays, below n = %.3f: T = %.4f ± %.4f",
      specimenName.c_str(), args.wavelengthNm, static_cast<unsigned long long>(args.study.rays),
      belowIndex, p.transmittance.mean, p.transmittance.standardError);
  PlotPanel panel{
      "transmitted light per steradian, normalised to the normal direction (paper Fig. 8)",
      "angle from the inward normal θ (°)",
      "relative transmitted intensity per sr",
      false,
      {model, diffuse}};
  plotPanels(args.study.plot, title, {panel}, 1, 1000, 650);
}

void runForwardProfile(const ForwardProfileArguments& args) {
  const WalkStudy study(args.study);
  const skin::Specimen& specimen = study.specimen();
  const skin::SkinOptics optics = study.optics(args.wavelengthNm);
  skin::WalkRunOptions run = study.run(0);
  run.walk.deepestLayer = skin::Layer::StratumBasale;
  run.walk.belowRefractiveIndex = belowRefractiveIndex(args.belowIndex, optics);
  run.tally.polarBins = args.polarBins;
  run.tally.azimuthBins = 1;  // azimuthally averaged
  const skin::SkinTally tally = simulateWithEstimator(args.study.estimator, {optics}, run).front();
  if (!MpiSession::isRoot()) return;  // only rank 0 prints and writes
  const skin::TransmissionProfile profile = skin::transmissionProfile(tally);
  writeTextAtomically(args.study.out, formatCsv(profile));
  std::printf("%s epidermis at %g nm, below n = %.4f: T = %.5f ± %.5f, R = %.5f, absorbed %.5f\n",
              specimen.name.c_str(), args.wavelengthNm, run.walk.belowRefractiveIndex,
              profile.transmittance.mean, profile.transmittance.standardError,
              tally.reflectance().mean, tally.absorptance().mean);
  if (!args.study.plot.empty())
    plotProfile(args, specimen.name, run.walk.belowRefractiveIndex, profile);
}

}  // namespace

void registerForwardProfileCommand(CLI::App& app) {
  auto args = std::make_shared<ForwardProfileArguments>();
  args->study.specimen.specimen = "S2";  // the paper's Fig. 8 specimen
  args->study.rays = 1000000;
  CLI::App* command = app.add_subcommand("forward-profile",
                                         "Angular profile of light transmitted through the "
                                         "epidermis at normal incidence (paper Fig. 8)");
  addWalkStudyOptions(*command, args->study, "Rays");
  addWavelengthOption(*command, args->wavelengthNm);
  command
      ->add_option("--polar-bins", args->polarBins,
                   "Bins of the angle from the inward normal over [0°, 90°]")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1800}))
      ->capture_default_str();
  command
      ->add_option(
          "--below-index", args->belowIndex,
          "Medium under the stratum basale: 'matched' (its own index) or a refractive index ≥ 1")
      ->capture_default_str();
  addStudyOutputOptions(*command, args->study, "CSV file to write, one row per polar bin",
                        "PNG plot to write");
  command->callback([args] { runForwardProfile(*args); });
}

}  // namespace hylios
