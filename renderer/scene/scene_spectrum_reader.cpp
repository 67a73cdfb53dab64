#include "renderer/scene/scene_spectrum_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "renderer/scene/emission_spectrum.h"
#include "skin/spectral_table.h"

namespace hylios {
namespace {

// Magnitude limits of spectra (issue 13; docs/scene-format.md): radiances and table values at most
// 1e12 (the film holds floats, 3.4e38, after sums over samples), a blackbody between 10 K and
// 1e6 K, an LED's centre and width within (0, 1e5] nm and a width of at least 1e-3 nm (a narrower
// Gaussian underflows to 0/0 at its centre).
constexpr double kMaxSpectrumValue = 1e12;
const NumberRange kScaleRange = NumberRange::closed(0, kMaxSpectrumValue);

using Reader = TomlTableReader;

skin::SpectralTable loadTable(const std::filesystem::path& file, const SourceLocation& where) {
  try {
    return skin::SpectralTable::loadCsv(file);
  } catch (const skin::SpectralTableError& error) {
    throw SceneError(where, error.what());
  }
}

/// `file = "x.csv"` (header row; first column wavelength in nm) and optionally `column`.
void readTableFile(Reader& r, EmissionDesc& e) {
  const std::filesystem::path file = r.existingFile("file");
  const SourceLocation where = r.whereValue("file");
  const skin::SpectralTable table = loadTable(file, where);
  std::size_t column = 0;
  if (r.has("column")) {
    const std::string name = r.string("column");
    try {
      column = table.columnIndex(name);
    } catch (const skin::SpectralTableError& error) {
      throw SceneError(r.whereValue("column"), error.what());
    }
  } else if (table.columnNames().size() != 1) {
    throw SceneError(where, fmt::format("'{}' has {} value columns; say which with 'column'",
                                        file.string(), table.columnNames().size()));
  }
  e.tableWavelengthNm = table.wavelengthsNm();
  e.tableValue = table.column(column);
  for (std::size_t i = 0; i < e.tableValue.size(); ++i)
    if (!(e.tableValue[i] >= 0 && e.tableValue[i] <= kMaxSpectrumValue))
      throw SceneError(where, fmt::format("'{}': value {} at {} nm must be in [0, 1e12]",
                                          file.string(), e.tableValue[i], e.tableWavelengthNm[i]));
}

void readTabulated(Reader& r, EmissionDesc& e) {
  if (r.has("file") && (r.has("wavelengths_nm") || r.has("values")))
    throw SceneError(r.whereValue("file"),
                     "a tabulated spectrum has either 'file' or 'wavelengths_nm' + 'values'");
  if (r.has("file")) return readTableFile(r, e);
  e.tableWavelengthNm = r.numbers("wavelengths_nm", 0, NumberRange::positive());
  e.tableValue = r.numbers("values", 0, kScaleRange);
  if (e.tableValue.size() != e.tableWavelengthNm.size())
    throw SceneError(r.whereValue("values"),
                     fmt::format("'values' has {} entries, 'wavelengths_nm' {}",
                                 e.tableValue.size(), e.tableWavelengthNm.size()));
  for (std::size_t i = 1; i < e.tableWavelengthNm.size(); ++i)
    if (!(e.tableWavelengthNm[i] > e.tableWavelengthNm[i - 1]))
      throw SceneError(r.whereValue("wavelengths_nm"), "'wavelengths_nm' must strictly ascend");
}

/// Every wavelength a band can ask for: its channels and both ends.
std::vector<std::pair<double, std::string>> bandWavelengths(const FilmDesc& film) {
  std::vector<std::pair<double, std::string>> out;
  for (const BandDesc& b : film.bands) {
    for (double nm : b.channelWavelengths()) out.emplace_back(nm, b.name);
    out.emplace_back(b.maxNm, b.name);
  }
  return out;
}

}  // namespace

EmissionDesc readSpectrum(const toml::table& t, const std::string& label, const TomlSource& src) {
  Reader r(t, label, src,
           {"type", "scale", "temperature_k", "centre_nm", "fwhm_nm", "wavelengths_nm", "values",
            "file", "column"});
  EmissionDesc e;
  e.where = r.where();
  const std::string type = r.choice("type", {"constant", "d65", "blackbody", "led", "tabulated"});
  e.scale = r.number("scale", kScaleRange, 1.0);
  if (type == "constant") e.kind = EmissionDesc::Kind::Constant;
  if (type == "d65") e.kind = EmissionDesc::Kind::D65;
  if (type == "blackbody") {
    e.kind = EmissionDesc::Kind::Blackbody;
    e.temperatureK = r.number("temperature_k", NumberRange::closed(10, 1e6));
  }
  if (type == "led") {
    e.kind = EmissionDesc::Kind::Led;
    e.centreNm = r.number("centre_nm", {0, 1e5, true, false});
    e.fwhmNm = r.number("fwhm_nm", NumberRange::closed(1e-3, 1e5));
  }
  if (type == "tabulated") {
    e.kind = EmissionDesc::Kind::Tabulated;
    readTabulated(r, e);
  }
  r.finish(fmt::format("a \"{}\" spectrum", type));
  return e;
}

EmissionDesc readEmission(Reader& r) {
  const toml::table* t = r.table("emission");
  if (!t) r.failHere(fmt::format("missing table 'emission' in {}", r.label()));
  return readSpectrum(*t, r.label() + " emission", r.source());
}

EmissionDesc readReflectance(Reader& r) {
  const toml::node* n = r.node("reflectance");
  if (!n) r.failHere(fmt::format("missing key 'reflectance' in {}", r.label()));
  EmissionDesc e;
  if (!n->is_table()) {
    e.scale = r.toNumber(*n, "'reflectance'", NumberRange::closed(0, 1));
    e.where = locationOf(r.source(), *n);
    return e;
  }
  e = readSpectrum(*n->as_table(), r.label() + " reflectance", r.source());
  double peak = e.scale;
  if (e.kind == EmissionDesc::Kind::D65)
    r.fail(*n, "a reflectance cannot be \"d65\" (an illuminant, not bounded by 1)");
  if (e.kind == EmissionDesc::Kind::Tabulated)
    for (double v : e.tableValue) peak = std::max(peak, v * e.scale);
  if (peak > 1)
    r.fail(*n, fmt::format("reflectance reaches {} somewhere; it must stay within [0, 1]", peak));
  return e;
}

void checkCoversBands(const EmissionDesc& e, const FilmDesc& film) {
  for (const auto& [nm, band] : bandWavelengths(film)) {
    try {
      evaluateEmission(e, nm);
    } catch (const SceneError& error) {
      throw SceneError(error.where(), fmt::format("{} (needed by band '{}')",
                                                  messageWithoutLocation(error), band));
    }
  }
}

}  // namespace hylios
