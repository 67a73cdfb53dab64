// hylios spectrum: total hemispherical reflectance of a specimen over wavelengths (paper Figs. 7, 9).
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

#include "renderer/atomic_file.h"
#include "renderer/commands.h"
#include "renderer/data_paths.h"
#include "renderer/gnuplot_plot.h"
#include "renderer/measured_spectrum.h"
#include "renderer/progress_bar.h"
#include "renderer/specimen_options.h"
#include "renderer/wavelength_list.h"
#include "skin/skin_simulation.h"

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
};

std::string formatCsv(const std::vector<double>& wavelengths, const std::vector<skin::SkinTally>& tallies) {
  std::ostringstream csv;
  csv << "wavelength_nm,reflectance,reflectance_stderr,surface_reflectance,subsurface_reflectance,"
         "transmittance,absorptance,absorptance_stderr,event_limited";
  for (skin::Layer layer : skin::kAllLayers) csv << ",absorptance_" << skin::layerName(layer);
  csv << "\n";
  char buffer[64];
  auto put = [&](double value) {
    std::snprintf(buffer, sizeof buffer, ",%.6g", value);
    csv << buffer;
  };
  for (std::size_t i = 0; i < wavelengths.size(); ++i) {
    const skin::SkinTally& t = tallies[i];
    std::snprintf(buffer, sizeof buffer, "%g", wavelengths[i]);
    csv << buffer;
    put(t.reflectance().mean);
    put(t.reflectance().standardError);
    put(t.surfaceReflectance().mean);
    put(t.subsurfaceReflectance().mean);
    put(t.transmittance().mean);  // 0 for the full stack: the hypodermis junction reflects all
    put(t.absorptance().mean);
    put(t.absorptance().standardError);
    put(t.eventLimited().mean);
    for (skin::Layer layer : skin::kAllLayers) put(t.absorptance(layer).mean);
    csv << "\n";
  }
  return csv.str();
}

void plotSpectrum(const SpectrumArguments& args, const std::string& specimenName,
                  const std::vector<double>& wavelengths, const std::vector<skin::SkinTally>& tallies,
                  const MeasuredSpectrum* measured) {
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
  if (measured) panel.series.push_back({"measured: " + measured->label, measured->wavelengthNm, measured->value, {}, "lines lw 2 lc rgb 'black'"});
  std::ostringstream title;
  title << "HyLIoS " << specimenName << ", incidence " << args.angleDeg << "°, " << args.rays << " rays per wavelength";
  plotPanels(args.plot, title.str(), {panel}, 1, 1100, 650);
}

void runSpectrum(const SpectrumArguments& args) {
  std::unique_ptr<tbb::global_control> threadLimit;
  if (args.threads > 0)
    threadLimit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, args.threads);
  const skin::Specimen specimen = loadSpecimenWithOverrides(args.specimen);
  const auto spectra = skin::SpectralDatabase::load(spectraDir());
  const std::vector<double> wavelengths = parseWavelengthList(args.wavelengths);
  std::unique_ptr<MeasuredSpectrum> measured;
  if (!args.measured.empty()) measured = std::make_unique<MeasuredSpectrum>(loadMeasuredSpectrum(args.measured));
  std::vector<skin::SkinOptics> optics;  // computed first, so a bad wavelength fails before any walk
  for (double w : wavelengths) optics.push_back(skin::computeSkinOptics(specimen, spectra, w));
  skin::WalkRunOptions run;
  run.incidenceDeg = args.angleDeg;
  run.rays = args.rays;
  run.seed = args.seed;
  std::vector<skin::SkinTally> tallies(wavelengths.size());
  ProgressBar progress("spectrum " + specimen.name, wavelengths.size());
  tbb::parallel_for(std::size_t{0}, wavelengths.size(), [&](std::size_t i) {
    tallies[i] = skin::simulateSkin(optics[i], run);
    progress.advance();
  });
  progress.finish();
  writeTextAtomically(args.out, formatCsv(wavelengths, tallies));
  if (measured) {
    std::vector<double> model;
    for (const auto& t : tallies) model.push_back(t.reflectance().mean);
    std::size_t compared = 0;
    const double rms = rmsDifference(wavelengths, model, *measured, &compared);
    std::cout << "RMS difference to '" << measured->label << "': " << rms << " over " << compared << " wavelengths\n";
  }
  if (!args.plot.empty()) plotSpectrum(args, specimen.name, wavelengths, tallies, measured.get());
}

}  // namespace

void registerSpectrumCommand(CLI::App& app) {
  auto args = std::make_shared<SpectrumArguments>();
  CLI::App* command = app.add_subcommand("spectrum", "Total hemispherical reflectance of a specimen over wavelengths (CSV, optional plot)");
  addSpecimenOptions(*command, args->specimen);
  command->add_option("--angle", args->angleDeg, "Incidence angle from the normal, degrees [0, 90)")->check(CLI::Range(0.0, 89.999));
  command->add_option("--wavelengths", args->wavelengths, "start:stop:step or a comma list, nm");
  command->add_option("--rays", args->rays, "Rays per wavelength")->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1} << 40));
  command->add_option("--seed", args->seed, "Random seed (same seed, same output at any thread count)");
  command->add_option("--out", args->out, "CSV file to write")->required();
  command->add_option("--plot", args->plot, "PNG plot to write");
  command->add_option("--measured", args->measured, "FILE:COLUMN of a measured curve to compare with (RMS printed)");
  command->add_option("--threads", args->threads, "Worker threads (default: all cores)")->check(CLI::Range(1, 1024));
  command->callback([args] { runSpectrum(*args); });
}

}  // namespace hylios
