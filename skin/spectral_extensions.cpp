#include "skin/spectral_extensions.h"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <initializer_list>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

#include "skin/spectral_database.h"

namespace hylios::skin {
namespace {

std::string position(const std::filesystem::path& file, const toml::source_region& where) {
  return fmt::format("{}:{}:{}", file.string(), where.begin.line, where.begin.column);
}

/// Reads the numeric keys of one TOML table, remembering which were used.
class SectionReader {
 public:
  SectionReader(const toml::table& root, std::string name, const std::filesystem::path& file)
      : name_(std::move(name)), file_(file) {
    const toml::node* node = root.at_path(name_).node();
    if (node == nullptr)
      throw SpectralDataError(fmt::format("{}: missing section [{}]", file_.string(), name_));
    table_ = node->as_table();
    if (table_ == nullptr)
      throw SpectralDataError(
          fmt::format("{}: '{}' must be a table", position(file_, node->source()), name_));
  }

  double number(const std::string& key) {
    used_.insert(key);
    const toml::node* node = table_->get(key);
    if (node == nullptr)
      throw SpectralDataError(fmt::format("{}: section [{}] lacks the key '{}'",
                                          position(file_, table_->source()), name_, key));
    if (const auto value = node->value<double>(); value && node->is_number()) return *value;
    throw SpectralDataError(
        fmt::format("{}: [{}] {} must be a number", position(file_, node->source()), name_, key));
  }

  double positive(const std::string& key) {
    const double value = number(key);
    if (!(value > 0))
      throw SpectralDataError(fmt::format("{}: [{}] {} must be > 0, got {}",
                                          position(file_, table_->get(key)->source()), name_, key,
                                          value));
    return value;
  }

  /// Throws on a key that no reader asked for (a typo would otherwise be silently ignored).
  void rejectUnknownKeys() const {
    for (const auto& [key, node] : *table_)
      if (used_.count(std::string(key.str())) == 0 && !node.is_table())
        throw SpectralDataError(fmt::format("{}: unknown key '{}' in [{}]",
                                            position(file_, node.source()), key.str(), name_));
  }

  AbsorptionBand band() {
    AbsorptionBand b;
    b.peakNm = positive("peak_nm");
    b.sigmaBlueEv = positive("sigma_blue_ev");
    b.sigmaRedEv = positive("sigma_red_ev");
    b.referenceNm = positive("reference_nm");
    b.referenceValue = positive("reference_value");
    b.multiplier = positive("multiplier");
    b.zeroFromNm = positive("zero_from_nm");
    rejectUnknownKeys();
    try {
      b.validate(name_.c_str());
    } catch (const std::invalid_argument& e) {
      throw SpectralDataError(fmt::format("{}: {}", position(file_, table_->source()), e.what()));
    }
    return b;
  }

 private:
  std::string name_;
  const std::filesystem::path& file_;
  const toml::table* table_ = nullptr;
  std::set<std::string> used_;
};

void rejectUnknownSections(const toml::table& root, const std::filesystem::path& file) {
  const std::set<std::string> known = {"domain", "melanin",   "hemoglobin",
                                       "lipid",  "bilirubin", "keratin",
                                       "dna",    "band",      "beta_carotene"};
  for (const auto& [key, node] : root)
    if (known.count(std::string(key.str())) == 0)
      throw SpectralDataError(
          fmt::format("{}: unknown section or key '{}'", position(file, node.source()), key.str()));
  const std::pair<const char*, std::set<std::string>> subsections[] = {
      {"band", {"urocanic_acid"}},
      {"keratin", {"tyrosine", "tryptophan", "phenylalanine"}},
      {"dna", {"adenine", "guanine", "cytosine", "thymine"}}};
  for (const auto& [section, names] : subsections)
    if (const toml::table* table = root[section].as_table())
      for (const auto& [key, node] : *table)
        if (node.is_table() && names.count(std::string(key.str())) == 0)
          throw SpectralDataError(fmt::format("{}: unknown table [{}.{}]",
                                              position(file, node.source()), section, key.str()));
}

/// [<parent>.<name>]: zero_from_nm and, for a mass-weighted molecule (keratin's amino acids), its
/// g_per_100g and molar_mass_g_per_mol. DNA's bases are weighted by mole fraction: no mass needed.
MoleculeShare readMolecule(const toml::table& root, const std::string& section, bool massWeighted,
                           const std::filesystem::path& file) {
  SectionReader reader(root, section, file);
  MoleculeShare m;
  if (massWeighted) {
    m.share = reader.positive("g_per_100g");
    m.molarMass = reader.positive("molar_mass_g_per_mol");
  }
  m.zeroFromNm = reader.positive("zero_from_nm");
  reader.rejectUnknownKeys();
  return m;
}

void requireOrdered(double low, double high, const char* what, const std::filesystem::path& file) {
  if (!(low < high))
    throw SpectralDataError(fmt::format("{}: {} needs {} < {}", file.string(), what, low, high));
}

/// Reads section `section`: each key, a positive number, into its field, in order; no other key.
void readPositives(const toml::table& root, const char* section, const std::filesystem::path& file,
                   std::initializer_list<std::pair<const char*, double*>> fields) {
  SectionReader reader(root, section, file);
  for (const auto& [key, field] : fields) *field = reader.positive(key);
  reader.rejectUnknownKeys();
}

/// Reads every section of a parsed extensions document; `tomlFile` names it in messages.
SpectralExtensions readExtensions(const toml::table& root, const std::filesystem::path& tomlFile) {
  rejectUnknownSections(root, tomlFile);
  SpectralExtensions x;

  readPositives(root, "domain", tomlFile, {{"min_nm", &x.domainMinNm}, {"max_nm", &x.domainMaxNm}});
  requireOrdered(x.domainMinNm, x.domainMaxNm, "[domain]", tomlFile);

  readPositives(root, "melanin", tomlFile,
                {{"eumelanin_fit_min_nm", &x.eumelaninFitMinNm},
                 {"pheomelanin_fit_min_nm", &x.pheomelaninFitMinNm}});

  readPositives(root, "hemoglobin", tomlFile,
                {{"prahl_molar_mass_g_per_mol", &x.prahlHemoglobinMolarMass},
                 {"zijlstra_molar_mass_g_per_mol", &x.zijlstraHemoglobinMolarMass},
                 {"floor_min_nm", &x.hemoglobinFloorMinNm},
                 {"floor_max_nm", &x.hemoglobinFloorMaxNm},
                 {"blood_water_volume_fraction", &x.bloodWaterVolumeFraction},
                 {"blood_hemoglobin_mg_per_ml", &x.bloodHemoglobinMgPerMl},
                 {"decay_length_nm", &x.hemoglobinDecayLengthNm}});
  requireOrdered(x.hemoglobinFloorMinNm, x.hemoglobinFloorMaxNm, "[hemoglobin] floor range",
                 tomlFile);
  requireOrdered(x.bloodWaterVolumeFraction, 1.0, "[hemoglobin] blood_water_volume_fraction",
                 tomlFile);

  readPositives(root, "lipid", tomlFile, {{"corn_oil_first_valid_nm", &x.cornOilFirstValidNm}});
  readPositives(
      root, "bilirubin", tomlFile,
      {{"molar_mass_g_per_mol", &x.bilirubinMolarMass}, {"zero_from_nm", &x.bilirubinZeroFromNm}});
  readPositives(root, "beta_carotene", tomlFile,
                {{"molar_mass_g_per_mol", &x.betaCaroteneMolarMass},
                 {"zero_from_nm", &x.betaCaroteneZeroFromNm}});

  readPositives(root, "keratin", tomlFile, {{"density_mg_per_ml", &x.keratin.densityMgPerMl}});
  for (auto [name, molecule] :
       {std::pair{"tyrosine", &x.keratin.tyrosine}, std::pair{"tryptophan", &x.keratin.tryptophan},
        std::pair{"phenylalanine", &x.keratin.phenylalanine}})
    *molecule = readMolecule(root, std::string("keratin.") + name, true, tomlFile);

  readPositives(root, "dna", tomlFile,
                {{"gc_fraction", &x.dna.gcFraction},
                 {"reference_nm", &x.dna.referenceNm},
                 {"reference_value", &x.dna.referenceValue}});
  requireOrdered(x.dna.gcFraction, 1.0, "[dna] gc_fraction", tomlFile);
  for (auto [name, molecule] :
       {std::pair{"adenine", &x.dna.adenine}, std::pair{"guanine", &x.dna.guanine},
        std::pair{"cytosine", &x.dna.cytosine}, std::pair{"thymine", &x.dna.thymine}})
    *molecule = readMolecule(root, std::string("dna.") + name, false, tomlFile);
  x.dna.guanine.share = x.dna.cytosine.share = x.dna.gcFraction / 2.0;
  x.dna.adenine.share = x.dna.thymine.share = (1.0 - x.dna.gcFraction) / 2.0;

  x.urocanicAcid = SectionReader(root, "band.urocanic_acid", tomlFile).band();
  return x;
}

}  // namespace

SpectralExtensions SpectralExtensions::load(const std::filesystem::path& tomlFile) {
  toml::table root;
  try {
    root = toml::parse_file(tomlFile.string());
  } catch (const toml::parse_error& e) {
    throw SpectralDataError(fmt::format("{}: {}", position(tomlFile, e.source()), e.description()));
  }
  return readExtensions(root, tomlFile);
}

SpectralExtensions SpectralExtensions::parse(const std::string& tomlText,
                                             const std::filesystem::path& sourceName) {
  toml::table root;
  try {
    root = toml::parse(tomlText, sourceName.string());
  } catch (const toml::parse_error& e) {
    throw SpectralDataError(
        fmt::format("{}: {}", position(sourceName, e.source()), e.description()));
  }
  return readExtensions(root, sourceName);
}

}  // namespace hylios::skin
