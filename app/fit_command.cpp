// hylios fit: fits freed specimen quantities to a measured reflectance curve (issue 14) by bounded
// Levenberg–Marquardt on the spectral walk with common random numbers (skin/specimen_fit.h), and
// writes the fitted specimen as a specimen file that `spectrum --specimen FILE` reads.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <unistd.h>

#include "app/commands.h"
#include "app/common_options.h"
#include "app/gnuplot_plot.h"
#include "app/measured_spectrum.h"
#include "app/option_checks.h"
#include "app/specimen_options.h"
#include "app/wavelength_list.h"
#include "renderer/scene/data_paths.h"
#include "skin/core/atomic_file.h"
#include "skin/core/thread_limit.h"
#include "skin/specimen_fit.h"
#include "skin/specimen_writer.h"

namespace hylios {
namespace {

struct FitArguments {
  SpecimenOptions specimen;
  std::string measured;
  double angleDeg = 45;
  std::string wavelengths = "400:700:10";
  std::string free = "melanosome,colloidal,blood,oxygenation,water_reduction";
  std::string out;
  std::string plot;
  std::uint64_t rays = 20000;
  std::uint64_t seed = 1;
  int maxIterations = 25;
  int threads = 0;
};

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ','))
    if (!item.empty()) items.push_back(item);
  return items;
}

std::string fmtValue(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g", v);
  return buffer;
}

std::string fitReport(const skin::FitResult& fit, const MeasuredSpectrum& measured, double seconds,
                      const FitArguments& args) {
  std::ostringstream out;
  out << "fit of " << fit.specimen.name << " to '" << measured.label << "' at " << args.angleDeg
      << "°, " << fit.model.size() << " wavelengths, " << args.rays << " rays per wavelength, seed "
      << args.seed << "\n";
  out << "  quantity                     start      fitted     ± 1σ       bounds\n";
  for (const auto& q : fit.quantities) {
    char line[256];
    std::snprintf(line, sizeof line, "  %-26s %9s  %9s  %9s   [%s, %s] %s%s\n",
                  q.quantity.name.c_str(), fmtValue(q.start).c_str(), fmtValue(q.value).c_str(),
                  q.atBound ? "at bound"
                  : q.uncertainty > q.quantity.upper - q.quantity.lower
                      ? "unconstr."
                      : fmtValue(q.uncertainty).c_str(),
                  fmtValue(q.quantity.lower).c_str(), fmtValue(q.quantity.upper).c_str(),
                  q.quantity.unit.c_str(), q.atBound ? " (at a bound)" : "");
    out << line;
  }
  for (const auto& q : fit.quantities)
    if (!q.atBound && q.uncertainty > q.quantity.upper - q.quantity.lower) {
      out << "  (unconstr.: σ wider than the bound range, the curve does not determine it)\n";
      break;
    }
  char line[256];
  std::snprintf(line, sizeof line,
                "RMS %.4f (start %.4f), %zu curve evaluations, %d iterations, %.1f s: %s\n",
                fit.rms, fit.startRms, fit.evaluations, fit.iterations, seconds,
                fit.stopReason.c_str());
  out << line;
  return out.str();
}

void plotFit(const FitArguments& args, const skin::FitResult& fit,
             const std::vector<double>& wavelengths, const std::vector<double>& target,
             const std::vector<skin::Estimate>& startModel, const MeasuredSpectrum& measured) {
  PlotSeries fitted{"fitted " + fit.specimen.name + " ± 2 s.e.", wavelengths, {}, {}, ""};
  for (const auto& e : fit.model) {
    fitted.y.push_back(e.mean);
    fitted.yError.push_back(2 * e.standardError);
  }
  PlotSeries start{"start " + fit.specimen.name, wavelengths, {}, {}, "lines lw 1 dt 2"};
  for (const auto& e : startModel) start.y.push_back(e.mean);
  PlotSeries meas{"measured: " + measured.label,
                  wavelengths,
                  target,
                  {},
                  "linespoints lw 2 pt 7 ps 0.6 lc rgb 'black'"};
  PlotPanel panel{"", "wavelength (nm)", "reflectance", false, {fitted, start, meas}};
  char title[160];
  std::snprintf(title, sizeof title, "hylios fit: RMS %.4f (start %.4f), %zu evaluations", fit.rms,
                fit.startRms, fit.evaluations);
  plotPanels(args.plot, title, {panel}, 1, 1100, 650);
}

/// Fails before the fit (minutes) when an output could not be written afterwards.
void checkOutputFolder(const std::string& option, const std::string& path) {
  if (path.empty()) return;
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty() && !std::filesystem::is_directory(parent))
    throw std::runtime_error(option + " '" + path + "': folder '" + parent.string() +
                             "' does not exist");
  if (std::filesystem::is_directory(path))
    throw std::runtime_error(option + " '" + path + "' is a folder");
}

void runFit(const FitArguments& args) {
  checkOutputFolder("--out", args.out);
  checkOutputFolder("--plot", args.plot);
  // The fitted specimen must not replace its start specimen or the measured curve (issue 13).
  const std::string measuredPath = args.measured.substr(0, args.measured.rfind(':'));
  checkOutputs(
      {{"--out", args.out}, {"--plot", args.plot, true}},
      {inputFile("--specimen", args.specimen.specimen), inputFile("--measured", measuredPath)});
  const ThreadLimit threadLimit(args.threads);
  const skin::Specimen start = loadSpecimenWithOverrides(args.specimen);
  const auto spectra = skin::SpectralDatabase::load(spectraDir());
  const std::vector<double> grid = parseWavelengthList(args.wavelengths);
  const MeasuredSpectrum measured = loadMeasuredSpectrum(args.measured);
  skin::FitOptions options;
  options.free = splitList(args.free);
  for (const auto& name : options.free)
    skin::fitQuantity(name);  // unknown names fail before any walk
  options.incidenceDeg = args.angleDeg;
  options.rays = args.rays;
  options.seed = args.seed;
  options.maxIterations = args.maxIterations;
  skin::FitTarget target;
  for (double w : grid)
    if (measured.covers(w)) {
      target.wavelengthNm.push_back(w);
      target.reflectance.push_back(measured.at(w));
    }
  if (target.wavelengthNm.empty())
    throw skin::FitError("--measured '" + args.measured + "' (" +
                         fmtValue(measured.wavelengthNm.front()) + "–" +
                         fmtValue(measured.wavelengthNm.back()) +
                         " nm) covers none of --wavelengths " + args.wavelengths);
  const auto t0 = std::chrono::steady_clock::now();
  const bool terminal = ::isatty(STDERR_FILENO) != 0;
  if (terminal)
    options.progress = [](std::size_t evaluations, double rms) {
      std::fprintf(stderr, "\rfit: %zu curve evaluations, best RMS %.4f", evaluations, rms);
    };
  const skin::FitResult fit = skin::fitSpecimen(start, spectra, target, options);
  if (terminal) std::fprintf(stderr, "\n");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::string report = fitReport(fit, measured, seconds, args);
  std::cout << report;
  std::string header = "Specimen fitted by `hylios fit` to " + args.measured + "\n" + report;
  writeTextAtomically(args.out, skin::formatSpecimenToml(fit.specimen, header));
  if (!args.plot.empty()) {
    const auto startModel = skin::modelReflectance(start, spectra, target.wavelengthNm, options);
    plotFit(args, fit, target.wavelengthNm, target.reflectance, startModel, measured);
  }
}

}  // namespace

void registerFitCommand(CLI::App& app) {
  auto args = std::make_shared<FitArguments>();
  std::string names;
  for (const auto& q : skin::fitQuantities()) names += (names.empty() ? "" : ", ") + q.name;
  CLI::App* command = app.add_subcommand("fit",
                                         "Fit freed specimen quantities to a measured reflectance "
                                         "curve (bounded least squares); writes a specimen file");
  addSpecimenOptions(*command, args->specimen);
  command
      ->add_option("--measured", args->measured,
                   "FILE:COLUMN of the measured curve (first column: nm)")
      ->required();
  addAngleOption(*command, args->angleDeg);
  command
      ->add_option("--wavelengths", args->wavelengths,
                   "start:stop:step or a comma list, nm (those the measurement covers are fitted)")
      ->capture_default_str();
  command->add_option("--free", args->free, "Comma list of quantities to fit, of: " + names)
      ->capture_default_str();
  command->add_option("--out", args->out, "Specimen file (TOML) to write")->required();
  command->add_option("--plot", args->plot, "PNG plot of measured, start and fitted curves");
  addRaysOption(*command, args->rays, "Rays per wavelength and curve evaluation", 100,
                std::uint64_t{1} << 32);
  addSeedOption(
      *command, args->seed,
      "Random seed in [0, 2^63-1], the same for every evaluation (common random numbers)");
  command
      ->add_option("--max-iterations", args->maxIterations,
                   "Levenberg–Marquardt iterations at most")
      ->check(CLI::Range(1, 1000));
  addThreadsOption(*command, args->threads);
  command->callback([args] { runFit(*args); });
}

}  // namespace hylios
