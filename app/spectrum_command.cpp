// hylios spectrum: total hemispherical reflectance of a specimen over wavelengths (paper Figs. 7,
// 9).
#include <tbb/parallel_for.h>

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "app/commands.h"
#include "app/common_options.h"
#include "app/enum_option.h"
#include "app/estimator_option.h"
#include "app/gnuplot_plot.h"
#include "app/measured_spectrum.h"
#include "app/mpi_session.h"
#include "app/mpi_spectral.h"
#include "app/option_checks.h"
#include "app/progress_bar.h"
#include "app/specimen_options.h"
#include "app/spectral_table_spectrum.h"
#include "app/spectrum_wavelength.h"
#include "app/wavelength_list.h"
#include "renderer/scene/data_paths.h"
#include "skin/core/atomic_file.h"
#include "skin/core/thread_limit.h"
#include "skin/effect_plan.h"
#include "skin/skin_mode.h"
#include "skin/skin_simulation.h"
#include "skin/spectral_simulation.h"

namespace hylios {
namespace {

struct SpectrumArguments {
  SpecimenOptions specimen;
  double angleDeg = 45;
  std::string wavelengths = "250:2500:5";
  std::uint64_t rays = 100000;
  std::uint64_t seed = 1;
  std::string out;
  std::string plot;
  std::string measured;
  int threads = 0;
  double effectTolerance =
      skin::kDefaultEffectTolerance;  ///< ε of the effect planner; 0: full model
  bool explain = false;
  skin::SkinMode skinModel =
      skin::SkinMode::Walk;  ///< Table: rays sampled from the cached exit table (skin/exit_table.h)
  skin::Estimator estimator = skin::Estimator::Spectral;  ///< PerWavelength: the reference
};

/// Full plan tables up to this many wavelengths, one summary line each beyond.
constexpr std::size_t kMaxExplainTables = 8;

void printPlans(const std::vector<std::optional<skin::EffectPlan>>& plans) {
  for (const auto& plan : plans)
    if (plan) std::cout << (plans.size() <= kMaxExplainTables ? plan->explain() : plan->summary());
}

std::string formatCsv(const std::vector<double>& wavelengths,
                      const std::vector<skin::SkinTally>& tallies,
                      const std::vector<std::optional<skin::EffectPlan>>& plans) {
  std::ostringstream csv;
  csv << "wavelength_nm,reflectance,reflectance_stderr,surface_reflectance,subsurface_reflectance,"
         "transmittance,absorptance,absorptance_stderr,event_limited";
  for (skin::Layer layer : skin::kAllLayers) csv << ",absorptance_" << skin::layerName(layer);
  csv << ",effect_bound\n";  // the effect planner's bound on |ΔR| (0: full model)
  char buffer[64];
  auto put = [&](double value) {
    std::snprintf(buffer, sizeof buffer, ",%.6g", value);
    csv << buffer;
  };
  for (std::size_t i = 0; i < wavelengths.size(); ++i) {
    const skin::SkinTally& t = tallies[i];
    csv << formatWavelength(wavelengths[i]);
    put(t.reflectance().mean);
    put(t.reflectance().standardError);
    put(t.surfaceReflectance().mean);
    put(t.subsurfaceReflectance().mean);
    put(t.transmittance().mean);  // 0 for the full stack: the hypodermis junction reflects all
    put(t.absorptance().mean);
    put(t.absorptance().standardError);
    put(t.eventLimited().mean);
    for (skin::Layer layer : skin::kAllLayers) put(t.absorptance(layer).mean);
    put(plans[i] ? plans[i]->droppedDepthBound : 0.0);
    csv << "\n";
  }
  return csv.str();
}

void plotSpectrum(const SpectrumArguments& args, const std::string& specimenName,
                  const std::vector<double>& wavelengths,
                  const std::vector<skin::SkinTally>& tallies, const MeasuredSpectrum* measured) {
  PlotSeries total{"total reflectance ± 1 s.e.", wavelengths, {}, {}, ""};
  PlotSeries surface{"surface", wavelengths, {}, {}, "lines lw 1 dt 2"};
  PlotSeries subsurface{"subsurface", wavelengths, {}, {}, "lines lw 1 dt 3"};
  for (const auto& t : tallies) {
    total.y.push_back(t.reflectance().mean);
    total.yError.push_back(t.reflectance().standardError);
    surface.y.push_back(t.surfaceReflectance().mean);
    subsurface.y.push_back(t.subsurfaceReflectance().mean);
  }
  PlotPanel panel{"", "wavelength (nm)", "reflectance", false, {total, surface, subsurface}};
  if (measured)
    panel.series.push_back({"measured: " + measured->label,
                            measured->wavelengthNm,
                            measured->value,
                            {},
                            "lines lw 2 lc rgb 'black'"});
  std::ostringstream title;
  title << "HyLIoS " << specimenName << ", incidence " << args.angleDeg << "°, " << args.rays
        << " rays per wavelength";
  plotPanels(args.plot, title.str(), {panel}, 1, 1100, 650);
}

/// The file of --measured FILE:COLUMN.
std::string measuredFile(const std::string& measured) {
  const auto colon = measured.rfind(':');
  return colon == std::string::npos ? measured : measured.substr(0, colon);
}

void runSpectrum(const SpectrumArguments& args) {
  shareRootVerdict([&] {  // under MPI: checked on rank 0, every rank stops with its verdict
    checkOutputs({{"--out", args.out}, {"--plot", args.plot, true}},
                 {inputFile("--specimen", args.specimen.specimen),
                  inputFile("--measured", measuredFile(args.measured))});
  });
  const ThreadLimit threadLimit(args.threads);
  const skin::Specimen specimen = loadSpecimenWithOverrides(args.specimen);
  const auto spectra = skin::SpectralDatabase::load(spectraDir());
  const std::vector<double> wavelengths = parseWavelengthList(args.wavelengths);
  std::unique_ptr<MeasuredSpectrum> measured;
  if (!args.measured.empty())
    measured = std::make_unique<MeasuredSpectrum>(loadMeasuredSpectrum(args.measured));
  std::vector<skin::SkinOptics>
      optics;  // computed first, so a bad wavelength fails before any walk
  for (double w : wavelengths) optics.push_back(skin::computeSkinOptics(specimen, spectra, w));
  skin::WalkRunOptions run;
  run.incidenceDeg = args.angleDeg;
  run.rays = args.rays;
  run.seed = args.seed;
  std::vector<skin::SkinTally> tallies(wavelengths.size());
  std::vector<std::optional<skin::EffectPlan>> plans(wavelengths.size());
  ProgressBar progress("spectrum " + specimen.name, wavelengths.size());
  if (args.estimator == skin::Estimator::Spectral && args.skinModel == skin::SkinMode::Walk) {
    // One path per bundle of wavelengths, the full model (no effect plan: bound 0).
    // Under MPI the chunks are divided among the ranks (app/mpi_spectral.h); the other branches
    // run whole on every rank.
    tallies = simulateSkinSpectralOnRanks(optics, skin::commandSpectralRun(run));
    progress.advance(wavelengths.size());
  } else if (args.estimator == skin::Estimator::Spectral) {
    // Table mode: each bundle's tables from one set of spectral walks (full model).
    tallies = spectralTableTallies(optics, args.angleDeg, args.rays, args.seed);
    progress.advance(wavelengths.size());
  } else {
    const SpectrumWavelengthSettings settings{args.angleDeg,        args.rays,    args.seed,
                                              args.effectTolerance, args.explain, args.skinModel};
    tbb::parallel_for(std::size_t{0}, wavelengths.size(), [&](std::size_t i) {
      SpectrumWavelengthResult result = simulateSpectrumWavelength(optics[i], settings);
      tallies[i] = std::move(result.tally);
      plans[i] = std::move(result.plan);
      progress.advance();
    });
  }
  progress.finish();
  if (!MpiSession::isRoot()) return;  // only rank 0 prints and writes
  if (args.explain) printPlans(plans);
  writeTextAtomically(args.out, formatCsv(wavelengths, tallies, plans));
  if (measured) {
    std::vector<double> model;
    for (const auto& t : tallies) model.push_back(t.reflectance().mean);
    std::size_t compared = 0;
    const double rms = rmsDifference(wavelengths, model, *measured, &compared);
    std::cout << "RMS difference to '" << measured->label << "': " << rms << " over " << compared
              << " wavelengths\n";
  }
  if (!args.plot.empty()) plotSpectrum(args, specimen.name, wavelengths, tallies, measured.get());
}

}  // namespace

void registerSpectrumCommand(CLI::App& app) {
  auto args = std::make_shared<SpectrumArguments>();
  CLI::App* command = app.add_subcommand(
      "spectrum",
      "Total hemispherical reflectance of a specimen over wavelengths (CSV, optional plot)");
  addSpecimenOptions(*command, args->specimen);
  command->add_option("--angle", args->angleDeg, "Incidence angle from the normal, degrees [0, 90)")
      ->check(finiteRange(0.0, 89.999));
  command->add_option("--wavelengths", args->wavelengths, "start:stop:step or a comma list, nm");
  addRaysOption(*command, args->rays, "Rays per wavelength");
  addSeedOption(*command, args->seed);
  command->add_option("--out", args->out, "CSV file to write")->required();
  command->add_option("--plot", args->plot, "PNG plot to write");
  command->add_option("--measured", args->measured,
                      "FILE:COLUMN of a measured curve to compare with (RMS printed)");
  addEnumOption(
      *command, "--skin-model", args->skinModel, skin::kSkinModeNames,
      "walk (exact HyLIoS walk per ray) or table (rays sampled from exit tables cached in "
      "$HYLIOS_CACHE_DIR, else $XDG_CACHE_HOME/hylios or ~/.cache/hylios)");
  addEstimatorOption(*command, args->estimator);
  addThreadsOption(*command, args->threads);
  command
      ->add_option(
          "--epsilon", args->effectTolerance,
          "Effect-planner tolerance (per-wavelength estimator, walk or table mode): processes "
          "whose summed optical depth stays below it are skipped, bounding the change of R by it "
          "(0 = simulate "
          "everything; default 1e-3)")
      ->check(finiteRange(0.0, 1.0));
  command->add_flag(
      "--explain", args->explain,
      "Print each wavelength's effect plan (process, layer, optical depth, kept or skipped; "
      "one line per wavelength beyond 8)");
  command->callback([args] { runSpectrum(*args); });
}

}  // namespace hylios
