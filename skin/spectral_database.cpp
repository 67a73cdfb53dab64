// Assembles each absorber's spectrum over the model's domain from the tables in assets/spectra/
// and the declared extensions in assets/spectra/extensions.toml. The unit derivations are listed in
// docs/absorber_units.md; the provenance of every piece in assets/spectra/SOURCES.md.
#include "skin/spectral_database.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

#include "skin/core/constants.h"
#include "skin/layer_composition.h"
#include "skin/piecewise_spectrum.h"
#include "skin/spectral_extensions.h"
#include "skin/spectral_table.h"

namespace hylios::skin {
namespace {

const double kLn10 = std::log(10.0);
using TablePtr = std::shared_ptr<const SpectralTable>;

TablePtr loadTable(const std::filesystem::path& dir, const char* file,
                   DuplicateWavelengths duplicates = DuplicateWavelengths::Reject,
                   MissingValues missing = MissingValues::Reject) {
  try {
    return std::make_shared<const SpectralTable>(
        SpectralTable::loadCsv(dir / file, duplicates, missing));
  } catch (const SpectralTableError& e) {
    throw SpectralDataError(e.what());
  }
}

std::size_t columnOf(const SpectralTable& table, const char* name) {
  try {
    return table.columnIndex(name);
  } catch (const SpectralTableError& e) {
    throw SpectralDataError(e.what());
  }
}

/// λ ↦ scale · (linear interpolation of one column).
PiecewiseSpectrum::Function scaledColumn(TablePtr table, std::size_t column, double scale) {
  return [table = std::move(table), column, scale](double nm) {
    return scale * table->interpolate(column, nm);
  };
}

PiecewiseSpectrum::Function constant(double value) {
  return [value](double) { return value; };
}

/// A one-column table of `scale`·(column) over the rows of `table` within [minNm, maxNm].
struct Samples {
  std::vector<double> wavelengthsNm;
  std::vector<double> values;
  void appendRows(const SpectralTable& table, std::size_t column, double scale, double minNm,
                  double maxNm, bool includeMin = true) {
    for (std::size_t i = 0; i < table.rowCount(); ++i) {
      const double nm = table.wavelengthsNm()[i];
      if ((includeMin ? nm >= minNm : nm > minNm) && nm <= maxNm) {
        wavelengthsNm.push_back(nm);
        values.push_back(scale * table.column(column)[i]);
      }
    }
  }
  TablePtr table(const std::string& name) const {
    try {
      return std::make_shared<const SpectralTable>(name, std::vector<std::string>{"value"},
                                                   wavelengthsNm,
                                                   std::vector<std::vector<double>>{values});
    } catch (const SpectralTableError& e) {
      throw SpectralDataError(e.what());
    }
  }
};

class Builder {
 public:
  Builder(std::filesystem::path dir, SpectralExtensions ext) : dir_(std::move(dir)), x_(ext) {}

  void requireFrom(const SpectralTable& t, double nm) const {
    if (t.minWavelengthNm() > nm)
      throw SpectralDataError(fmt::format("{}: starts at {} nm; the model needs it from {} nm",
                                          t.sourceName(), t.minWavelengthNm(), nm));
  }

  /// Water's absorption (μa from the k column) or real index (n column) over the whole domain.
  PiecewiseSpectrum water(TablePtr table, const char* column, bool absorption,
                          const char* origin) const {
    requireFrom(*table, x_.domainMinNm);
    if (table->maxWavelengthNm() < x_.domainMaxNm)
      throw SpectralDataError(fmt::format("{}: ends at {} nm, before {} nm", table->sourceName(),
                                          table->maxWavelengthNm(), x_.domainMaxNm));
    const std::size_t col = columnOf(*table, column);
    PiecewiseSpectrum s(absorption ? "water" : "water refractive index");
    PiecewiseSpectrum::Function f = scaledColumn(table, col, 1.0);
    if (absorption)  // μa = 4π k / λ, λ in cm
      f = [f](double nm) { return 4.0 * kPi * f(nm) / (nm * 1e-7); };
    s.append(x_.domainMinNm, x_.domainMaxNm, origin, std::move(f));
    return s;
  }

  PiecewiseSpectrum melanin(Absorber a, const char* file, double fitMinNm) const {
    const TablePtr t = loadTable(dir_, file);
    requireFrom(*t, x_.domainMinNm);
    const std::size_t col = columnOf(*t, "specific_extinction_cm-1_per_mg_mL-1");
    const double slope = logLogSlope(*t, col, fitMinNm);
    const double edgeNm = t->maxWavelengthNm();
    const double edgeValue = t->column(col).back();
    const double amplitude = edgeValue / std::pow(edgeNm, slope);  // continuous at the edge
    PiecewiseSpectrum s(std::string(absorberName(a)));
    s.append(x_.domainMinNm, edgeNm, "Sarna & Swartz 1988 table", scaledColumn(t, col, kLn10));
    s.append(edgeNm, x_.domainMaxNm,
             fmt::format("power law λ^{:.4f} fitted to the table above {} nm", slope, fitMinNm),
             [amplitude, slope](double nm) { return kLn10 * amplitude * std::pow(nm, slope); });
    return s;
  }

  /// Least-squares slope of ln(value) against ln(λ) over the rows at and above fitMinNm.
  static double logLogSlope(const SpectralTable& t, std::size_t col, double fitMinNm) {
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < t.rowCount(); ++i) {
      const double nm = t.wavelengthsNm()[i], v = t.column(col)[i];
      if (nm < fitMinNm) continue;
      if (!(v > 0))
        throw SpectralDataError(
            fmt::format("{}: non-positive value {} at {} nm in the power-law fit range",
                        t.sourceName(), v, nm));
      const double lx = std::log(nm), ly = std::log(v);
      n += 1;
      sx += lx;
      sy += ly;
      sxx += lx * lx;
      sxy += lx * ly;
    }
    if (n < 3)
      throw SpectralDataError(fmt::format("{}: fewer than 3 rows above {} nm to fit the power law",
                                          t.sourceName(), fitMinNm));
    const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    if (!(slope < 0))
      throw SpectralDataError(
          fmt::format("{}: the power-law fit above {} nm does not decrease (slope {})",
                      t.sourceName(), fitMinNm, slope));
    return slope;
  }

  /// Non-water absorption of blood per mg/mL of hemoglobin (see extensions.toml [hemoglobin]).
  double hemoglobinFloor(const PiecewiseSpectrum& waterMuA) const {
    const TablePtr blood = loadTable(dir_, "whole_blood_bosschaart_2014.csv");
    const std::size_t oxy = columnOf(*blood, "mua_oxy_mm-1"),
                      deoxy = columnOf(*blood, "mua_deoxy_mm-1");
    std::vector<double> residuals;
    for (std::size_t i = 0; i < blood->rowCount(); ++i) {
      const double nm = blood->wavelengthsNm()[i];
      if (nm < x_.hemoglobinFloorMinNm || nm > x_.hemoglobinFloorMaxNm) continue;
      const double bloodMuA =
          10.0 * 0.5 * (blood->column(oxy)[i] + blood->column(deoxy)[i]);  // mm⁻¹ → cm⁻¹
      residuals.push_back((bloodMuA - x_.bloodWaterVolumeFraction * waterMuA(nm)) /
                          x_.bloodHemoglobinMgPerMl);
    }
    if (residuals.empty())
      throw SpectralDataError(fmt::format("{}: no rows in the floor range", blood->sourceName()));
    std::sort(residuals.begin(), residuals.end());
    const std::size_t m = residuals.size() / 2;
    const double median =
        residuals.size() % 2 ? residuals[m] : 0.5 * (residuals[m - 1] + residuals[m]);
    if (!(median > 0))
      throw SpectralDataError(fmt::format("{}: the non-water residual's median is {} (not > 0)",
                                          blood->sourceName(), median));
    return median;
  }

  /// Appends the tail above the spectrum's current end (1000 nm): decays to the floor F.
  void appendHemoglobinTail(PiecewiseSpectrum& s, double floor) const {
    const double fromNm = s.coverage().maxNm;
    const double start = s(fromNm), length = x_.hemoglobinDecayLengthNm;
    s.append(
        fromNm, x_.domainMaxNm, "declared tail: decay to the Bosschaart 2014 non-water floor",
        [=](double nm) { return floor + (start - floor) * std::exp(-(nm - fromNm) / length); });
  }

  std::vector<PiecewiseSpectrum> hemoglobins(double floor) const {
    const TablePtr prahl = loadTable(dir_, "hemoglobin_oxy_deoxy_prahl.csv");
    requireFrom(*prahl, x_.domainMinNm);
    const double toPrahlMass = kLn10 / x_.prahlHemoglobinMolarMass;
    const double toZijlstraMass = kLn10 / x_.zijlstraHemoglobinMolarMass;
    const auto hbo2 =
        scaledColumn(prahl, columnOf(*prahl, "molar_extinction_HbO2_cm-1_M-1"), toPrahlMass);
    const auto hb =
        scaledColumn(prahl, columnOf(*prahl, "molar_extinction_Hb_cm-1_M-1"), toPrahlMass);
    const double prahlEnd = prahl->maxWavelengthNm();

    auto fromPrahl = [&](Absorber a, const PiecewiseSpectrum::Function& f) {
      PiecewiseSpectrum s(std::string(absorberName(a)));
      s.append(x_.domainMinNm, prahlEnd, "Prahl 1999 table", f);
      appendHemoglobinTail(s, floor);
      return s;
    };
    // HbO2's shape scaled to meet `g` at `atNm` (the fill for missing UV / NIR stretches).
    auto scaledHbO2 = [&](const PiecewiseSpectrum::Function& g, double atNm) {
      const double factor = g(atNm) / hbo2(atNm);
      return [hbo2, factor](double nm) { return factor * hbo2(nm); };
    };
    auto zijlstra = [&](const char* file, const char* column) {
      const TablePtr t = loadTable(dir_, file);
      return std::make_pair(t, scaledColumn(t, columnOf(*t, column), toZijlstraMass));
    };

    std::vector<PiecewiseSpectrum> out;
    out.push_back(fromPrahl(Absorber::Oxyhemoglobin, hbo2));
    out.push_back(fromPrahl(Absorber::Deoxyhemoglobin, hb));

    {  // carboxyhemoglobin: HbO2 shape below 450 nm, Zijlstra 450–1000 nm, tail.
      const auto [t, hbco] =
          zijlstra("carboxyhemoglobin_zijlstra_2000.csv", "molar_extinction_HbCO_cm-1_M-1");
      PiecewiseSpectrum s("carboxyhemoglobin");
      s.append(x_.domainMinNm, t->minWavelengthNm(), "Prahl HbO2 shape scaled at 450 nm",
               scaledHbO2(hbco, t->minWavelengthNm()));
      s.append(t->minWavelengthNm(), t->maxWavelengthNm(), "Zijlstra 2000 table", hbco);
      appendHemoglobinTail(s, floor);
      out.push_back(std::move(s));
    }
    {  // methemoglobin: HbO2 shape below 390 nm, van Assendelft 390–<450, Zijlstra 450–1000, tail.
      const TablePtr assendelft = loadTable(dir_, "methemoglobin_van_assendelft_1970.csv");
      const TablePtr zmet = loadTable(dir_, "methemoglobin_zijlstra_2000.csv");
      Samples merged;  // per-haem L/mmol/cm × 4000 = per-tetramer cm⁻¹/M
      merged.appendRows(*assendelft,
                        columnOf(*assendelft, "absorptivity_MetHb_per_heme_L_mmol-1_cm-1"),
                        4000.0 * toZijlstraMass, 0.0, std::nextafter(zmet->minWavelengthNm(), 0.0));
      merged.appendRows(*zmet, columnOf(*zmet, "molar_extinction_MetHb_cm-1_M-1"), toZijlstraMass,
                        0.0, zmet->maxWavelengthNm());
      const TablePtr table = merged.table("methemoglobin (van Assendelft 1970 + Zijlstra 2000)");
      const auto metHb = scaledColumn(table, 0, 1.0);
      PiecewiseSpectrum s("methemoglobin");
      s.append(x_.domainMinNm, table->minWavelengthNm(), "Prahl HbO2 shape scaled at 390 nm",
               scaledHbO2(metHb, table->minWavelengthNm()));
      s.append(table->minWavelengthNm(), table->maxWavelengthNm(),
               "van Assendelft 1970 + Zijlstra 2000 tables", metHb);
      appendHemoglobinTail(s, floor);
      out.push_back(std::move(s));
    }
    {  // sulfhemoglobin: HbO2 shape below 450 nm, Zijlstra 450–800 nm, HbO2 shape to 1000 nm, tail.
      const auto [t, shb] =
          zijlstra("sulfhemoglobin_zijlstra_2000.csv", "molar_extinction_SHb_cm-1_M-1");
      PiecewiseSpectrum s("sulfhemoglobin");
      s.append(x_.domainMinNm, t->minWavelengthNm(), "Prahl HbO2 shape scaled at 450 nm",
               scaledHbO2(shb, t->minWavelengthNm()));
      s.append(t->minWavelengthNm(), t->maxWavelengthNm(), "Zijlstra 2000 table", shb);
      s.append(t->maxWavelengthNm(), prahlEnd, "Prahl HbO2 shape scaled at 800 nm",
               scaledHbO2(shb, t->maxWavelengthNm()));
      appendHemoglobinTail(s, floor);
      out.push_back(std::move(s));
    }
    return out;
  }

  /// PhotochemCAD molar table × `scale` up to its declared end of band, zero beyond.
  PiecewiseSpectrum photochemcad(const std::string& substance, const char* file, double scale,
                                 double zeroFromNm) const {
    const TablePtr t = loadTable(dir_, file);
    requireFrom(*t, x_.domainMinNm);
    if (!(zeroFromNm > x_.domainMinNm && zeroFromNm <= t->maxWavelengthNm()))
      throw SpectralDataError(fmt::format("{}: zero_from_nm = {} nm must lie within {}–{} nm",
                                          t->sourceName(), zeroFromNm, x_.domainMinNm,
                                          t->maxWavelengthNm()));
    const std::size_t col = columnOf(*t, "molar_extinction_cm-1_M-1");
    Samples used;  // rows before the end of band, then 0 at zeroFromNm
    used.appendRows(*t, col, scale, 0.0, std::nextafter(zeroFromNm, 0.0));
    for (std::size_t i = 0; i < used.values.size(); ++i)
      if (used.wavelengthsNm[i] >= x_.domainMinNm && used.values[i] < 0)
        throw SpectralDataError(
            fmt::format("{}: negative value at {} nm, before the declared end of band {} nm",
                        t->sourceName(), used.wavelengthsNm[i], zeroFromNm));
    used.wavelengthsNm.push_back(zeroFromNm);
    used.values.push_back(0.0);
    PiecewiseSpectrum s(substance);
    s.append(x_.domainMinNm, zeroFromNm, "PhotochemCAD table",
             scaledColumn(used.table(t->sourceName()), 0, 1.0));
    s.append(zeroFromNm, x_.domainMaxNm, "declared zero: the band has ended", constant(0.0));
    return s;
  }

  /// Bilirubin, β-carotene: natural-log absorption per mg/mL from the molar table.
  PiecewiseSpectrum carotenoid(Absorber a, const char* file, double molarMass,
                               double zeroFromNm) const {
    return photochemcad(std::string(absorberName(a)), file, kLn10 / molarMass, zeroFromNm);
  }

  /// Σ weight_i · molecule_i(λ) up to `endNm` (the last molecule's end of band), zero beyond.
  PiecewiseSpectrum weightedSum(Absorber a, std::vector<std::pair<double, PiecewiseSpectrum>> terms,
                                double endNm, const std::string& origin) const {
    PiecewiseSpectrum s(std::string(absorberName(a)));
    s.append(x_.domainMinNm, endNm, origin, [terms = std::move(terms)](double nm) {
      double sum = 0;
      for (const auto& [weight, molecule] : terms) sum += weight * molecule(nm);
      return sum;
    });
    if (endNm < x_.domainMaxNm)
      s.append(endNm, x_.domainMaxNm, "declared zero: every molecule's band has ended",
               constant(0.0));
    return s;
  }

  /// Solid keratin per volume fraction: its aromatic amino acids (see extensions.toml [keratin]).
  PiecewiseSpectrum keratin() const {
    const KeratinComposition& k = x_.keratin;
    std::vector<std::pair<double, PiecewiseSpectrum>> terms;
    double endNm = x_.domainMinNm;
    for (auto [name, file, m] :
         {std::tuple{"tyrosine", "tyrosine_photochemcad.csv", k.tyrosine},
          std::tuple{"tryptophan", "tryptophan_photochemcad.csv", k.tryptophan},
          std::tuple{"phenylalanine", "phenylalanine_photochemcad.csv", k.phenylalanine}}) {
      // mg/mL of the amino acid per unit volume fraction of keratin × ζ per mg/mL of it.
      terms.emplace_back(k.densityMgPerMl * m.share / 100.0,
                         photochemcad(name, file, kLn10 / m.molarMass, m.zeroFromNm));
      endNm = std::max(endNm, m.zeroFromNm);
    }
    return weightedSum(Absorber::Keratin, std::move(terms), endNm,
                       "PhotochemCAD tyrosine + tryptophan + phenylalanine (Block 1951 weights)");
  }

  /// Double-stranded DNA per mg/mL: base-composition-weighted bases, scaled at the reference.
  PiecewiseSpectrum dna() const {
    const DnaComposition& d = x_.dna;
    std::vector<std::pair<double, PiecewiseSpectrum>> terms;  // molar ε (decadic) first
    double endNm = x_.domainMinNm;
    for (auto [name, file, m] : {std::tuple{"adenine", "adenine_photochemcad.csv", d.adenine},
                                 std::tuple{"guanine", "guanine_photochemcad.csv", d.guanine},
                                 std::tuple{"cytosine", "cytosine_photochemcad.csv", d.cytosine},
                                 std::tuple{"thymine", "thymine_photochemcad.csv", d.thymine}}) {
      terms.emplace_back(m.share, photochemcad(name, file, 1.0, m.zeroFromNm));
      endNm = std::max(endNm, m.zeroFromNm);
    }
    double mixAtReference = 0;
    for (const auto& [share, base] : terms) mixAtReference += share * base(d.referenceNm);
    if (!(mixAtReference > 0))
      throw SpectralDataError(fmt::format("DNA: the bases' sum at reference_nm = {} nm is {}",
                                          d.referenceNm, mixAtReference));
    const double scale = kLn10 * d.referenceValue / mixAtReference;
    for (auto& term : terms) term.first *= scale;
    return weightedSum(Absorber::Dna, std::move(terms), endNm,
                       "PhotochemCAD A + G + C + T by base composition, scaled at the reference");
  }

  PiecewiseSpectrum lipid() const {
    const TablePtr vanVeen = loadTable(dir_, "fat_absorption_van_veen_2004.csv");
    const TablePtr lard = loadTable(dir_, "lipid_lard_absorption_watt_2025.csv",
                                    DuplicateWavelengths::Reject, MissingValues::DropRow);
    const TablePtr anderson = loadTable(dir_, "fat_absorption_anderson_2006_digitized.csv",
                                        DuplicateWavelengths::Average);
    const TablePtr cornOil = loadTable(dir_, "lipid_corn_oil_absorption_watt_2025.csv");
    Samples merged;  // cm⁻¹ of pure fat
    merged.appendRows(*vanVeen, columnOf(*vanVeen, "absorption_coefficient_m-1"), 0.01, 0.0,
                      vanVeen->maxWavelengthNm());
    merged.appendRows(*lard, columnOf(*lard, "mua_cm-1"), 1.0, vanVeen->maxWavelengthNm(),
                      std::nextafter(anderson->minWavelengthNm(), 0.0), false);
    merged.appendRows(*anderson, columnOf(*anderson, "mua_cm-1"), 1.0, 0.0,
                      anderson->maxWavelengthNm());
    merged.appendRows(*cornOil, columnOf(*cornOil, "mua_cm-1"), 1.0,
                      std::max(anderson->maxWavelengthNm(), x_.cornOilFirstValidNm), x_.domainMaxNm,
                      false);
    const TablePtr table =
        merged.table("lipid (van Veen 2004 + lard/corn oil Watt 2025 + Anderson 2006)");
    if (table->maxWavelengthNm() < x_.domainMaxNm)
      throw SpectralDataError(fmt::format("{}: ends at {} nm, before {} nm", table->sourceName(),
                                          table->maxWavelengthNm(), x_.domainMaxNm));
    PiecewiseSpectrum s("lipid");
    s.append(x_.domainMinNm, table->minWavelengthNm(), "declared: van Veen's 429 nm value held",
             constant(table->column(0).front()));
    s.append(table->minWavelengthNm(), x_.domainMaxNm, "merged lipid tables",
             scaledColumn(table, 0, 1.0));
    return s;
  }

  PiecewiseSpectrum band(Absorber a, const AbsorptionBand& b) const {
    PiecewiseSpectrum s(std::string(absorberName(a)));
    const double end = std::min(b.zeroFromNm, x_.domainMaxNm);
    s.append(x_.domainMinNm, end, "band model",
             [b](double nm) { return b.naturalLogAbsorption(nm); });
    if (end < x_.domainMaxNm)
      s.append(end, x_.domainMaxNm, "declared zero beyond the band", constant(0.0));
    return s;
  }

  const SpectralExtensions& extensions() const { return x_; }
  const std::filesystem::path& dir() const { return dir_; }

 private:
  std::filesystem::path dir_;
  SpectralExtensions x_;
};

}  // namespace

struct SpectralDatabase::Impl {
  std::vector<PiecewiseSpectrum> spectra;  // indexed by index(Absorber)
  std::optional<PiecewiseSpectrum> waterIndex;
};

SpectralDatabase SpectralDatabase::load(const std::filesystem::path& spectraDir) {
  const Builder build(spectraDir, SpectralExtensions::load(spectraDir / "extensions.toml"));
  const SpectralExtensions& x = build.extensions();
  const TablePtr segelstein = loadTable(spectraDir, "water_refractive_index_segelstein_1981.csv");
  PiecewiseSpectrum water = build.water(segelstein, "k_imag", true, "Segelstein 1981 table");
  std::vector<PiecewiseSpectrum> hemoglobins = build.hemoglobins(build.hemoglobinFloor(water));

  auto impl = std::make_unique<Impl>();
  // The layers' dispersion follows Hale & Querry's n (docs/interpretations.md, "Refractive indices
  // away from 1300 nm"); water's absorption keeps Segelstein's finer k table.
  impl->waterIndex =
      build.water(loadTable(spectraDir, "water_refractive_index_hale_querry_1973.csv"), "n_real",
                  false, "Hale & Querry 1973 table");
  for (Absorber a : kAllAbsorbers) {
    switch (a) {
      case Absorber::Keratin:
        impl->spectra.push_back(build.keratin());
        break;
      case Absorber::Dna:
        impl->spectra.push_back(build.dna());
        break;
      case Absorber::UrocanicAcid:
        impl->spectra.push_back(build.band(a, x.urocanicAcid));
        break;
      case Absorber::Eumelanin:
        impl->spectra.push_back(
            build.melanin(a, "eumelanin_sarna_swartz.csv", x.eumelaninFitMinNm));
        break;
      case Absorber::Pheomelanin:
        impl->spectra.push_back(
            build.melanin(a, "pheomelanin_sarna_swartz.csv", x.pheomelaninFitMinNm));
        break;
      case Absorber::Oxyhemoglobin:
        impl->spectra.push_back(hemoglobins[0]);
        break;
      case Absorber::Deoxyhemoglobin:
        impl->spectra.push_back(hemoglobins[1]);
        break;
      case Absorber::Carboxyhemoglobin:
        impl->spectra.push_back(hemoglobins[2]);
        break;
      case Absorber::Methemoglobin:
        impl->spectra.push_back(hemoglobins[3]);
        break;
      case Absorber::Sulfhemoglobin:
        impl->spectra.push_back(hemoglobins[4]);
        break;
      case Absorber::Bilirubin:
        impl->spectra.push_back(build.carotenoid(a, "bilirubin_photochemcad.csv",
                                                 x.bilirubinMolarMass, x.bilirubinZeroFromNm));
        break;
      case Absorber::BetaCarotene:
        impl->spectra.push_back(build.carotenoid(a, "beta_carotene_photochemcad.csv",
                                                 x.betaCaroteneMolarMass,
                                                 x.betaCaroteneZeroFromNm));
        break;
      case Absorber::Water:
        impl->spectra.push_back(water);
        break;
      case Absorber::Lipid:
        impl->spectra.push_back(build.lipid());
        break;
    }
  }
  return SpectralDatabase(std::move(impl));
}

double SpectralDatabase::specificAbsorption(Absorber absorber, double wavelengthNm) const {
  return impl_->spectra.at(index(absorber))(wavelengthNm);
}

ConcentrationUnit SpectralDatabase::concentrationUnit(Absorber absorber) {
  return absorberConcentrationUnit(absorber);  // one table: skin/layer_composition.cpp
}

SpectralCoverage SpectralDatabase::coverage(Absorber absorber) const {
  return impl_->spectra.at(index(absorber)).coverage();
}

double SpectralDatabase::waterRefractiveIndex(double wavelengthNm) const {
  return (*impl_->waterIndex)(wavelengthNm);
}

SpectralDatabase::SpectralDatabase(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
SpectralDatabase::SpectralDatabase(SpectralDatabase&&) noexcept = default;
SpectralDatabase& SpectralDatabase::operator=(SpectralDatabase&&) noexcept = default;
SpectralDatabase::~SpectralDatabase() = default;

}  // namespace hylios::skin
