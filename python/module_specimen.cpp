#include "python/module_specimen.h"

#include <pybind11/stl.h>

#include "app/specimen_options.h"
#include "renderer/scene/data_paths.h"
#include "skin/specimen_writer.h"
#include "skin/spectral_database.h"

namespace hylios::python {

namespace py = pybind11;

namespace {

PySpecimen loadSpecimen(const std::string& nameOrPath, const std::vector<std::string>& overrides) {
  SpecimenOptions options;
  options.specimen = nameOrPath;
  options.overrides = overrides;
  return {loadSpecimenWithOverrides(options)};
}

/// The overrides of `overrides` ("key=value", as --set) applied in order to a copy; the parsing and
/// messages of app/specimen_options.cpp.
PySpecimen withOverrides(const PySpecimen& s, const std::vector<std::string>& overrides) {
  PySpecimen result = s;
  applyOverrides(result.specimen, overrides);
  return result;
}

}  // namespace

std::vector<skin::SkinOptics> opticsOf(const skin::Specimen& specimen,
                                       const std::vector<double>& wavelengths) {
  const auto spectra = skin::SpectralDatabase::load(spectraDir());
  std::vector<skin::SkinOptics> optics;  // first, so that a bad wavelength fails before any walk
  for (double w : wavelengths) optics.push_back(skin::computeSkinOptics(specimen, spectra, w));
  return optics;
}

void bindSpecimen(py::module_& m) {
  py::class_<PySpecimen>(m, "_Specimen", "A loaded specimen (see hylios.Specimen)")
      .def_property_readonly("name", [](const PySpecimen& s) { return s.specimen.name; })
      .def_property_readonly("source_file",
                             [](const PySpecimen& s) { return s.specimen.sourceFile.string(); })
      .def(
          "to_toml",
          [](const PySpecimen& s, const std::string& header) {
            return skin::formatSpecimenToml(s.specimen, header);
          },
          py::arg("header") = "", "The specimen as specimen-file TOML text")
      .def(
          "values",
          [](const PySpecimen& s) {
            const skin::Specimen& x = s.specimen;
            py::dict d;
            d["surface_fold_aspect_ratio"] = x.surfaceFoldAspectRatio;
            d["thickness_cm"] = std::vector<double>(x.thicknessCm.begin(), x.thicknessCm.end());
            d["melanosome_fraction"] =
                std::vector<double>(x.melanosomeFraction.begin(), x.melanosomeFraction.end());
            d["colloidal_melanin_fraction"] = std::vector<double>(
                x.colloidalMelaninFraction.begin(), x.colloidalMelaninFraction.end());
            d["blood_fraction"] =
                std::vector<double>(x.bloodFraction.begin(), x.bloodFraction.end());
            d["melanosome_eumelanin_mg_per_ml"] = x.melanosomeEumelanin_mgPerMl;
            d["melanosome_pheomelanin_mg_per_ml"] = x.melanosomePheomelanin_mgPerMl;
            d["melanosome_major_axis_um"] = x.melanosomeMajorAxisUm;
            d["melanosome_minor_axis_um"] = x.melanosomeMinorAxisUm;
            d["oxygenated_blood_fraction"] = x.oxygenatedBloodFraction;
            d["water_reduction"] = x.waterReduction;
            return d;
          },
          "The main specimen quantities (fractions in [0, 1], per layer where a list)");

  m.def("load_specimen", &loadSpecimen, py::arg("name_or_path"), py::arg("overrides"),
        "Loads a specimen by name (S1..S4) or path and applies 'key=value' overrides in order");
  m.def(
      "specimen_from_toml",
      [](const std::string& text, const std::string& sourceName) {
        return PySpecimen{skin::parseSpecimen(text, sourceName)};
      },
      py::arg("text"), py::arg("source_name"), "Parses specimen-file TOML text");
  m.def("with_overrides", &withOverrides, py::arg("specimen"), py::arg("overrides"),
        "A copy of the specimen with 'key=value' overrides applied in order");
  m.def("override_keys", &skin::overrideKeys, "The keys of specimen overrides");
}

}  // namespace hylios::python
