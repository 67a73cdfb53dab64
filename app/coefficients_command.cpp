// `hylios coefficients`: every layer's optical coefficients of a specimen over a wavelength list,
// as CSV (one row per wavelength and layer) and optionally a PNG (absorbers' specific spectra as
// in the paper's Fig. 2, and the layers' total absorption).
//
//   hylios coefficients --specimen S1 --wavelengths 250:2500:5 --out coeffs.csv
//                       [--plot coeffs.png] [--set melanosome_percent=3 ...]
//
// CSV columns: wavelength_nm, layer, mu_a_per_cm (total, Eq. 3), mu_s_rayleigh_per_cm (Eq. 4),
// mu_melanosome_per_cm (Eq. 6), refractive_index, then mu_a_<absorber>_per_cm for every absorber
// in kAllAbsorbers order. Numbers are printed with %.6g. Any non-finite value is an error.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/gnuplot_plot.h"
#include "app/option_checks.h"
#include "app/specimen_options.h"
#include "app/wavelength_list.h"
#include "renderer/scene/data_paths.h"
#include "skin/core/atomic_file.h"
#include "skin/core/enum_names.h"
#include "skin/skin_optics.h"
#include "skin/specimen.h"
#include "skin/spectral_database.h"

namespace hylios {
namespace {

struct CoefficientsOptions {
  SpecimenOptions specimen;  ///< --specimen (required here) and --set, as in every command
  std::string wavelengths = "250:2500:5";
  std::string csvPath;
  std::string plotPath;
};

std::string csvHeader() {
  std::string header =
      "wavelength_nm,layer,mu_a_per_cm,mu_s_rayleigh_per_cm,mu_melanosome_per_cm,refractive_index";
  for (skin::Absorber a : skin::kAllAbsorbers)
    header += fmt::format(",mu_a_{}_per_cm", skin::absorberName(a));
  return header + "\n";
}

std::string checked(double value, double nm, skin::Layer layer, const char* what) {
  if (!std::isfinite(value))
    throw std::runtime_error(
        fmt::format("{} of {} at {} nm is {}", what, skin::layerName(layer), nm, value));
  return fmt::format("{:.6g}", value);
}

std::string csvRows(const skin::SkinOptics& optics) {
  std::string rows;
  const double nm = optics.wavelengthNm;
  for (skin::Layer l : skin::kAllLayers) {
    const skin::LayerOptics& o = optics[l];
    rows += fmt::format("{},{},{},{},{},{}", formatWavelength(nm), skin::layerName(l),
                        checked(o.muATotal_perCm, nm, l, "mu_a"),
                        checked(o.muRayleigh_perCm, nm, l, "mu_s_rayleigh"),
                        checked(o.melanosome.mu_perCm, nm, l, "mu_melanosome"),
                        checked(o.refractiveIndex, nm, l, "refractive index"));
    for (skin::Absorber a : skin::kAllAbsorbers)
      rows += "," + checked(o.muA_perCm[skin::index(a)], nm, l, "mu_a of an absorber");
    rows += "\n";
  }
  return rows;
}

std::string unitLabel(skin::ConcentrationUnit unit) {
  static constexpr EnumNames<skin::ConcentrationUnit, 3> kLabels{
      {{skin::ConcentrationUnit::VolumeFraction, "per volume fraction"},
       {skin::ConcentrationUnit::MassConcentration, "per mg/mL"},
       {skin::ConcentrationUnit::MolarConcentration, "per mol/L"}}};
  return std::string(enumName(unit, kLabels));
}

/// "stratum_corneum" -> "stratum corneum" (gnuplot's enhanced text reads '_' as a subscript).
std::string plotLabel(std::string_view name) {
  std::string label(name);
  std::replace(label.begin(), label.end(), '_', ' ');
  return label;
}

/// Solid lines for the first 8 series of a panel, dashed after (gnuplot has 8 line colours).
std::string lineStyle(std::size_t seriesIndex) {
  return seriesIndex < 8 ? "lines lw 2" : "lines lw 2 dt 2";
}

/// Keeps the positive points only (a log axis cannot show zeros).
void addPositive(PlotSeries& series, double x, double y) {
  if (y > 0) {
    series.x.push_back(x);
    series.y.push_back(y);
  }
}

void writePlot(const std::filesystem::path& png, const skin::Specimen& specimen,
               const skin::SpectralDatabase& spectra, const std::vector<skin::SkinOptics>& optics) {
  PlotPanel absorbers{"Specific absorption of the absorbers (paper Fig. 2)",
                      "wavelength (nm)",
                      "specific absorption (cm^{-1} per unit)",
                      true,
                      {}};
  for (skin::Absorber a : skin::kAllAbsorbers) {
    PlotSeries series;
    series.title = fmt::format("{} ({})", plotLabel(skin::absorberName(a)),
                               unitLabel(skin::SpectralDatabase::concentrationUnit(a)));
    series.style = lineStyle(absorbers.series.size());
    for (const skin::SkinOptics& o : optics)
      addPositive(series, o.wavelengthNm, spectra.specificAbsorption(a, o.wavelengthNm));
    if (!series.x.empty()) absorbers.series.push_back(std::move(series));
  }
  PlotPanel layers{"Total absorption coefficient per layer, specimen " + specimen.name,
                   "wavelength (nm)",
                   "{/Symbol m}_a (cm^{-1})",
                   true,
                   {}};
  for (skin::Layer l : skin::kAllLayers) {
    PlotSeries series;
    series.title = plotLabel(skin::layerName(l));
    series.style = lineStyle(layers.series.size());
    for (const skin::SkinOptics& o : optics)
      addPositive(series, o.wavelengthNm, o[l].muATotal_perCm);
    if (!series.x.empty()) layers.series.push_back(std::move(series));
  }
  plotPanels(png, "HyLIoS coefficients, specimen " + specimen.name, {absorbers, layers}, 1, 1200,
             1400);
}

void runCoefficients(const CoefficientsOptions& options) {
  checkOutputs({{"--out", options.csvPath}, {"--plot", options.plotPath, true}},
               {inputFile("--specimen", options.specimen.specimen)});
  const std::vector<double> wavelengths = parseWavelengthList(options.wavelengths);
  const skin::Specimen specimen = loadSpecimenWithOverrides(options.specimen);
  const skin::SpectralDatabase spectra = skin::SpectralDatabase::load(spectraDir());

  std::vector<skin::SkinOptics> optics;
  optics.reserve(wavelengths.size());
  std::string csv = csvHeader();
  for (double nm : wavelengths) {
    optics.push_back(skin::computeSkinOptics(specimen, spectra, nm));
    csv += csvRows(optics.back());
  }
  writeTextAtomically(options.csvPath, csv);
  std::cout << fmt::format("wrote {} ({} wavelengths x {} layers, specimen {})\n", options.csvPath,
                           wavelengths.size(), skin::kLayerCount, specimen.name);
  if (!options.plotPath.empty()) {
    writePlot(options.plotPath, specimen, spectra, optics);
    std::cout << fmt::format("wrote {}\n", options.plotPath);
  }
}

}  // namespace

void registerCoefficientsCommand(CLI::App& app) {
  auto options = std::make_shared<CoefficientsOptions>();
  CLI::App* command = app.add_subcommand(
      "coefficients", "Write every layer's optical coefficients of a specimen (CSV, optional PNG)");
  command
      ->add_option("--specimen", options->specimen.specimen,
                   "S1..S4 (scenes/specimens/) or the path of a specimen .toml file")
      ->required();
  command
      ->add_option("--wavelengths", options->wavelengths, "start:stop:step or a comma list, in nm")
      ->capture_default_str();
  command->add_option("--out", options->csvPath, "CSV file to write")->required();
  command->add_option("--plot", options->plotPath, "PNG file to write (needs gnuplot)");
  addOverrideOption(*command, options->specimen);
  command->callback([options] { runCoefficients(*options); });
}

}  // namespace hylios
