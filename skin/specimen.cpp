// Specimen files (TOML) and overrides. The file layout is described by a schema table below:
// every key with its unit, admissible range and destination field; anything else is an error.
#include "skin/specimen.h"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <string_view>

#include "skin/core/toml_location.h"

namespace hylios::skin {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Admissible values of a number, with the phrase used in messages.
struct Range {
  double min = 0;
  double max = kInfinity;
  bool minExclusive = false;

  bool contains(double v) const { return (minExclusive ? v > min : v >= min) && v <= max; }
  std::string describe() const {
    if (max == kInfinity) return fmt::format("must be {} {}", minExclusive ? ">" : ">=", min);
    return fmt::format("must be in {}{}, {}]", minExclusive ? "(" : "[", min, max);
  }
};

const Range kPercent{0, 100, false};
const Range kNonNegative{0, kInfinity, false};
const Range kPositive{0, kInfinity, true};
const Range kRefractiveIndex{1, kInfinity, false};

using Setter = std::function<void(Specimen&, double)>;

/// One numeric key of a table: its name (unit in the suffix), range, and what it sets. Percent
/// keys store value/100.
struct NumberKey {
  std::string key;
  Range range;
  Setter set;
};

struct TableSchema {
  std::string name;  ///< "" for the root
  std::vector<NumberKey> numbers;
  std::vector<std::string> strings;  ///< string keys handled by the caller
};

Setter layerArray(std::array<double, kLayerCount> Specimen::*field, Layer layer, double scale) {
  return [field, layer, scale](Specimen& s, double v) { (s.*field)[index(layer)] = v * scale; };
}
Setter fixedArray(std::array<double, kLayerCount> FixedParameters::*field,
                  std::vector<Layer> layers, double scale) {
  return [field, layers, scale](Specimen& s, double v) {
    for (Layer l : layers) (s.fixed.*field)[index(l)] = v * scale;
  };
}
Setter fixedValue(double FixedParameters::*field, double scale = 1.0) {
  return [field, scale](Specimen& s, double v) { s.fixed.*field = v * scale; };
}
Setter specimenValue(double Specimen::*field, double scale) {
  return [field, scale](Specimen& s, double v) { s.*field = v * scale; };
}

const std::vector<Layer> kPigmented = {Layer::StratumGranulosum, Layer::StratumSpinosum,
                                       Layer::StratumBasale};
const std::vector<Layer> kDermis = {Layer::PapillaryDermis, Layer::ReticularDermis};

std::vector<TableSchema> buildSchema() {
  using FP = FixedParameters;
  std::vector<TableSchema> schema;
  schema.push_back(
      {"",
       {{"surface_fold_aspect_ratio", kPositive,
         specimenValue(&Specimen::surfaceFoldAspectRatio, 1.0)},
        {"skin_dna_mg_per_ml", kNonNegative, fixedValue(&FP::dna_mgPerMl)},
        {"water_reduction_percent", kPercent, specimenValue(&Specimen::waterReduction, 0.01)}},
       {"name"}});
  const Layer sc = Layer::StratumCorneum;
  schema.push_back(
      {"stratum_corneum",
       {{"thickness_cm", kNonNegative, layerArray(&Specimen::thicknessCm, sc, 1.0)},
        {"refractive_index_at_1300nm", kRefractiveIndex,
         fixedArray(&FP::refractiveIndexAt1300nm, {sc}, 1.0)},
        {"water_percent", kPercent, fixedArray(&FP::waterFraction, {sc}, 0.01)},
        {"lipid_percent", kPercent, fixedArray(&FP::lipidFraction, {sc}, 0.01)},
        {"keratin_percent", kPercent, fixedValue(&FP::stratumCorneumKeratinFraction, 0.01)},
        {"urocanic_acid_mol_per_l", kNonNegative,
         fixedValue(&FP::stratumCorneumUrocanicAcid_molPerL)},
        {"beta_carotene_mg_per_ml", kNonNegative,
         fixedValue(&FP::stratumCorneumBetaCarotene_mgPerMl)}},
       {}});
  schema.push_back(
      {"epidermis",
       {{"refractive_index_at_1300nm", kRefractiveIndex,
         fixedArray(&FP::refractiveIndexAt1300nm, kPigmented, 1.0)},
        {"water_percent", kPercent, fixedArray(&FP::waterFraction, kPigmented, 0.01)},
        {"lipid_percent", kPercent, fixedArray(&FP::lipidFraction, kPigmented, 0.01)},
        {"keratin_percent", kPercent, fixedValue(&FP::epidermisKeratinFraction, 0.01)},
        {"beta_carotene_mg_per_ml", kNonNegative, fixedValue(&FP::epidermisBetaCarotene_mgPerMl)}},
       {}});
  for (Layer l : kPigmented)
    schema.push_back(
        {std::string(layerName(l)),
         {{"thickness_cm", kNonNegative, layerArray(&Specimen::thicknessCm, l, 1.0)},
          {"melanosome_percent", kPercent, layerArray(&Specimen::melanosomeFraction, l, 0.01)},
          {"colloidal_melanin_percent", kPercent,
           layerArray(&Specimen::colloidalMelaninFraction, l, 0.01)}},
         {}});
  schema.push_back(
      {"melanosomes",
       {{"major_axis_um", kPositive, specimenValue(&Specimen::melanosomeMajorAxisUm, 1.0)},
        {"minor_axis_um", kPositive, specimenValue(&Specimen::melanosomeMinorAxisUm, 1.0)},
        {"eumelanin_mg_per_ml", kNonNegative,
         specimenValue(&Specimen::melanosomeEumelanin_mgPerMl, 1.0)},
        {"pheomelanin_mg_per_ml", kNonNegative,
         specimenValue(&Specimen::melanosomePheomelanin_mgPerMl, 1.0)},
        {"refractive_index_at_1300nm", kRefractiveIndex, fixedValue(&FP::melaninRefractiveIndex)}},
       {"arrangement"}});
  for (Layer l : kDermis)
    schema.push_back({std::string(layerName(l)),
                      {{"thickness_cm", kNonNegative, layerArray(&Specimen::thicknessCm, l, 1.0)},
                       {"blood_percent", kPercent, layerArray(&Specimen::bloodFraction, l, 0.01)},
                       {"refractive_index_at_1300nm", kRefractiveIndex,
                        fixedArray(&FP::refractiveIndexAt1300nm, {l}, 1.0)},
                       {"water_percent", kPercent, fixedArray(&FP::waterFraction, {l}, 0.01)},
                       {"lipid_percent", kPercent, fixedArray(&FP::lipidFraction, {l}, 0.01)}},
                      {}});
  schema.push_back(
      {"blood",
       {{"oxygenated_percent", kPercent, specimenValue(&Specimen::oxygenatedBloodFraction, 0.01)},
        {"hemoglobin_mg_per_ml", kNonNegative, fixedValue(&FP::bloodHemoglobin_mgPerMl)},
        {"methemoglobin_mg_per_ml", kNonNegative, fixedValue(&FP::bloodMethemoglobin_mgPerMl)},
        {"carboxyhemoglobin_mg_per_ml", kNonNegative,
         fixedValue(&FP::bloodCarboxyhemoglobin_mgPerMl)},
        {"sulfhemoglobin_mg_per_ml", kNonNegative, fixedValue(&FP::bloodSulfhemoglobin_mgPerMl)},
        {"bilirubin_mg_per_ml", kNonNegative, fixedValue(&FP::bloodBilirubin_mgPerMl)},
        {"beta_carotene_mg_per_ml", kNonNegative, fixedValue(&FP::bloodBetaCarotene_mgPerMl)}},
       {}});
  return schema;
}

const std::vector<TableSchema>& schema() {
  static const std::vector<TableSchema> s = buildSchema();
  return s;
}

// ---- messages with positions --------------------------------------------------------------

[[noreturn]] void fail(const std::string& source, const toml::source_region& region,
                       const std::string& message) {
  throw SpecimenError(tomlLocation(source, region) + ": " + message);
}

/// The key with its unit suffix removed ("thickness_mm" -> "thickness"), to recognise a known
/// quantity given in a unit we do not accept.
std::string_view unitStem(std::string_view key) {
  static const std::array<std::string_view, 22> suffixes = {
      "_mg_per_ml", "_g_per_l",    "_mg_per_dl",  "_g_per_dl",  "_g_per_ml", "_ug_per_ml",
      "_mol_per_l", "_mmol_per_l", "_umol_per_l", "_at_1300nm", "_percent",  "_fraction",
      "_permille",  "_cm",         "_mm",         "_um",        "_nm",       "_m",
      "_in",        "_ratio",      "_per_cm",     "_per_mm"};
  std::string_view best = key;
  for (std::string_view suffix : suffixes)
    if (key.size() > suffix.size() && key.substr(key.size() - suffix.size()) == suffix &&
        key.size() - suffix.size() < best.size())
      best = key.substr(0, key.size() - suffix.size());
  return best;
}

std::string tableLabel(const std::string& table) {
  return table.empty() ? "the top level" : "[" + table + "]";
}

std::string unknownKeyMessage(std::string_view key, const TableSchema& table,
                              const std::vector<std::string>& subtables) {
  std::vector<std::string> known;
  for (const auto& n : table.numbers) known.push_back(n.key);
  for (const auto& s : table.strings) known.push_back(s);
  for (const auto& s : subtables) known.push_back(s);
  for (const auto& k : known)
    if (unitStem(k) == unitStem(key))
      return fmt::format("unknown key '{}' (expected {}) in {}", key, k, tableLabel(table.name));
  std::string list;
  for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
  return fmt::format("unknown key '{}' in {} (known keys: {})", key, tableLabel(table.name), list);
}

// ---- reading one table ----------------------------------------------------------------------

std::vector<std::string> subtableNames() {
  std::vector<std::string> names;
  for (const auto& t : schema())
    if (!t.name.empty()) names.push_back(t.name);
  return names;
}

double readNumber(const toml::node& node, const NumberKey& key, const std::string& source) {
  if (!node.is_number())
    fail(source, node.source(),
         fmt::format("'{}' must be a number, got {}", key.key, tomlTypeName(node.type())));
  const double value = node.value<double>().value_or(std::nan(""));
  if (!std::isfinite(value))
    fail(source, node.source(), fmt::format("'{}' = {} is not finite", key.key, value));
  if (!key.range.contains(value))
    fail(source, node.source(), fmt::format("'{}' = {} {}", key.key, value, key.range.describe()));
  return value;
}

std::string readString(const toml::node& node, std::string_view key, const std::string& source) {
  if (!node.is_string())
    fail(source, node.source(),
         fmt::format("'{}' must be a string, got {}", key, tomlTypeName(node.type())));
  return *node.value<std::string>();
}

MelanosomeArrangement parseArrangement(const toml::node& node, const std::string& source) {
  const std::string text = readString(node, "arrangement", source);
  if (const auto arrangement = findEnum(text, kArrangementNames)) return *arrangement;
  std::string names;
  for (const auto& n : kArrangementNames)
    names += (names.empty() ? "\"" : ", \"") + std::string(n.name) + "\"";
  fail(source, node.source(), fmt::format("'arrangement' = \"{}\" is not one of {}", text, names));
}

/// Checks keys of `table` against `schemaTable` and stores the values. Subtables are allowed
/// only at the root.
void readTable(const toml::table& table, const TableSchema& schemaTable, Specimen& specimen,
               const std::string& source) {
  const bool isRoot = schemaTable.name.empty();
  const std::vector<std::string> subtables = isRoot ? subtableNames() : std::vector<std::string>{};
  for (auto&& [key, node] : table) {
    const std::string_view k = key.str();
    bool known = std::find(subtables.begin(), subtables.end(), k) != subtables.end() ||
                 std::find(schemaTable.strings.begin(), schemaTable.strings.end(), k) !=
                     schemaTable.strings.end();
    for (const auto& n : schemaTable.numbers) known = known || n.key == k;
    if (!known) fail(source, key.source(), unknownKeyMessage(k, schemaTable, subtables));
  }
  const auto missingMessage = [&](std::string_view k) {
    return fmt::format("missing key '{}' in {}", k, tableLabel(schemaTable.name));
  };
  for (const auto& n : schemaTable.numbers) {
    const toml::node* node = table.get(n.key);
    if (!node) fail(source, table.source(), missingMessage(n.key));
    n.set(specimen, readNumber(*node, n, source));
  }
  for (const auto& s : schemaTable.strings) {
    const toml::node* node = table.get(s);
    if (!node) fail(source, table.source(), missingMessage(s));
    if (s == "name") specimen.name = readString(*node, s, source);
    if (s == "arrangement") specimen.arrangement = parseArrangement(*node, source);
  }
}

void checkCrossFields(const toml::table& root, const Specimen& s, const std::string& source) {
  if (s.name.empty()) fail(source, root.get("name")->source(), "'name' must not be empty");
  if (s.melanosomeMinorAxisUm > s.melanosomeMajorAxisUm)
    fail(source, root["melanosomes"]["minor_axis_um"].node()->source(),
         fmt::format("'minor_axis_um' = {} exceeds 'major_axis_um' = {} (melanosomes are prolate)",
                     s.melanosomeMinorAxisUm, s.melanosomeMajorAxisUm));
}

// ---- overrides ------------------------------------------------------------------------------

struct OverrideKey {
  std::string key;
  Range range;
  Setter set;
};

std::vector<OverrideKey> buildOverrideKeys() {
  std::vector<OverrideKey> keys = {
      {"melanosome_percent", kPercent,
       [](Specimen& s, double v) {
         for (Layer l : kPigmented) s.melanosomeFraction[index(l)] = v / 100;
       }},
      {"colloidal_melanin_percent", kPercent,
       [](Specimen& s, double v) {
         for (Layer l : kPigmented) s.colloidalMelaninFraction[index(l)] = v / 100;
       }},
      {"blood_percent", kPercent,
       [](Specimen& s, double v) {
         for (Layer l : kDermis) s.bloodFraction[index(l)] = v / 100;
       }},
      {"water_reduction_percent", kPercent, specimenValue(&Specimen::waterReduction, 0.01)},
      {"oxygenation_percent", kPercent, specimenValue(&Specimen::oxygenatedBloodFraction, 0.01)},
      {"surface_fold_aspect_ratio", kPositive,
       specimenValue(&Specimen::surfaceFoldAspectRatio, 1.0)},
      {"melanosome_eumelanin_mg_per_ml", kNonNegative,
       specimenValue(&Specimen::melanosomeEumelanin_mgPerMl, 1.0)},
      {"melanosome_pheomelanin_mg_per_ml", kNonNegative,
       specimenValue(&Specimen::melanosomePheomelanin_mgPerMl, 1.0)},
  };
  for (Layer l : kAllLayers)
    keys.push_back({std::string(layerName(l)) + ".thickness_cm", kNonNegative,
                    layerArray(&Specimen::thicknessCm, l, 1.0)});
  for (Layer l : kPigmented) {
    keys.push_back({std::string(layerName(l)) + ".melanosome_percent", kPercent,
                    layerArray(&Specimen::melanosomeFraction, l, 0.01)});
    keys.push_back({std::string(layerName(l)) + ".colloidal_melanin_percent", kPercent,
                    layerArray(&Specimen::colloidalMelaninFraction, l, 0.01)});
  }
  for (Layer l : kDermis)
    keys.push_back({std::string(layerName(l)) + ".blood_percent", kPercent,
                    layerArray(&Specimen::bloodFraction, l, 0.01)});
  return keys;
}

const std::vector<OverrideKey>& overrideTable() {
  static const std::vector<OverrideKey> keys = buildOverrideKeys();
  return keys;
}

// ---- validation of a specimen built in code --------------------------------------------------

void checkValue(const Specimen& s, const std::string& what, double value, const Range& range) {
  if (!std::isfinite(value) || !range.contains(value))
    throw SpecimenError(fmt::format("specimen '{}': {} = {} {}", s.name, what, value,
                                    std::isfinite(value) ? range.describe() : "is not finite"));
}

}  // namespace

Specimen parseSpecimen(const std::string& tomlText, const std::string& sourceName) {
  toml::table root;
  try {
    root = toml::parse(tomlText, sourceName);
  } catch (const toml::parse_error& e) {
    fail(sourceName, e.source(), std::string(e.description()));
  }
  Specimen specimen;
  for (const auto& tableSchema : schema()) {
    if (tableSchema.name.empty()) {
      readTable(root, tableSchema, specimen, sourceName);
      continue;
    }
    const toml::node* node = root.get(tableSchema.name);
    if (!node) fail(sourceName, root.source(), fmt::format("missing table [{}]", tableSchema.name));
    if (!node->is_table())
      fail(sourceName, node->source(),
           fmt::format("'{}' must be a table, got {}", tableSchema.name,
                       tomlTypeName(node->type())));
    readTable(*node->as_table(), tableSchema, specimen, sourceName);
  }
  checkCrossFields(root, specimen, sourceName);
  validateSpecimen(specimen);
  return specimen;
}

Specimen loadSpecimen(const std::string& nameOrPath, const std::filesystem::path& specimenDir) {
  std::filesystem::path path = nameOrPath;
  const bool isName = nameOrPath.find('/') == std::string::npos && path.extension() != ".toml";
  if (isName) path = specimenDir / (nameOrPath + ".toml");
  std::error_code error;
  if (std::filesystem::is_directory(path, error))
    throw SpecimenError(fmt::format("specimen '{}': '{}' is a folder, not a specimen file",
                                    nameOrPath, path.string()));
  std::ifstream in(path);
  if (!in) {
    if (isName)
      throw SpecimenError(
          fmt::format("unknown specimen '{}': no file '{}'", nameOrPath, path.string()));
    throw SpecimenError(fmt::format("cannot open specimen file '{}'", path.string()));
  }
  std::stringstream text;
  text << in.rdbuf();
  Specimen specimen = parseSpecimen(text.str(), path.string());
  specimen.sourceFile = path;
  return specimen;
}

void applyOverride(Specimen& specimen, const SpecimenOverride& o) {
  const std::string where = o.origin.empty() ? "override" : o.origin;
  for (const auto& key : overrideTable()) {
    if (key.key != o.key) continue;
    if (!std::isfinite(o.value))
      throw SpecimenError(fmt::format("{}: {} = {} is not finite", where, o.key, o.value));
    if (!key.range.contains(o.value))
      throw SpecimenError(
          fmt::format("{}: {} = {} {}", where, o.key, o.value, key.range.describe()));
    key.set(specimen, o.value);
    return;
  }
  std::string list;
  for (const auto& k : overrideKeys()) list += (list.empty() ? "" : ", ") + k;
  throw SpecimenError(
      fmt::format("{}: unknown specimen override '{}' (known: {})", where, o.key, list));
}

std::vector<std::string> overrideKeys() {
  std::vector<std::string> keys;
  for (const auto& k : overrideTable()) keys.push_back(k.key);
  return keys;
}

void validateSpecimen(const Specimen& s) {
  checkValue(s, "surface_fold_aspect_ratio", s.surfaceFoldAspectRatio, kPositive);
  checkValue(s, "water_reduction", s.waterReduction, {0, 1, false});
  checkValue(s, "oxygenated_blood_fraction", s.oxygenatedBloodFraction, {0, 1, false});
  for (Layer l : kAllLayers) {
    const std::string name(layerName(l));
    checkValue(s, name + " thickness_cm", s.thicknessCm[index(l)], kNonNegative);
    checkValue(s, name + " melanosome fraction", s.melanosomeFraction[index(l)], {0, 1, false});
    checkValue(s, name + " colloidal melanin fraction", s.colloidalMelaninFraction[index(l)],
               {0, 1, false});
    checkValue(s, name + " blood fraction", s.bloodFraction[index(l)], {0, 1, false});
    checkValue(s, name + " water fraction", s.fixed.waterFraction[index(l)], {0, 1, false});
    checkValue(s, name + " lipid fraction", s.fixed.lipidFraction[index(l)], {0, 1, false});
    checkValue(s, name + " refractive index", s.fixed.refractiveIndexAt1300nm[index(l)],
               kRefractiveIndex);
    const bool pigmented = isPigmentedEpidermis(l);
    const bool dermis = l == Layer::PapillaryDermis || l == Layer::ReticularDermis;
    if ((!pigmented &&
         (s.melanosomeFraction[index(l)] > 0 || s.colloidalMelaninFraction[index(l)] > 0)) ||
        (!dermis && s.bloodFraction[index(l)] > 0))
      throw SpecimenError(
          fmt::format("specimen '{}': {} holds melanin or blood that the model "
                      "places only in the epidermis (melanin) or dermis (blood)",
                      s.name, name));
  }
  checkValue(s, "melanosome major_axis_um", s.melanosomeMajorAxisUm, kPositive);
  checkValue(s, "melanosome minor_axis_um", s.melanosomeMinorAxisUm,
             {0, s.melanosomeMajorAxisUm, true});
  checkValue(s, "melanosome eumelanin_mg_per_ml", s.melanosomeEumelanin_mgPerMl, kNonNegative);
  checkValue(s, "melanosome pheomelanin_mg_per_ml", s.melanosomePheomelanin_mgPerMl, kNonNegative);
  const FixedParameters& f = s.fixed;
  checkValue(s, "melanin refractive index", f.melaninRefractiveIndex, kRefractiveIndex);
  checkValue(s, "stratum corneum keratin fraction", f.stratumCorneumKeratinFraction, {0, 1, false});
  checkValue(s, "epidermis keratin fraction", f.epidermisKeratinFraction, {0, 1, false});
  for (const auto& [what, value] : std::initializer_list<std::pair<const char*, double>>{
           {"blood hemoglobin_mg_per_ml", f.bloodHemoglobin_mgPerMl},
           {"blood methemoglobin_mg_per_ml", f.bloodMethemoglobin_mgPerMl},
           {"blood carboxyhemoglobin_mg_per_ml", f.bloodCarboxyhemoglobin_mgPerMl},
           {"blood sulfhemoglobin_mg_per_ml", f.bloodSulfhemoglobin_mgPerMl},
           {"blood bilirubin_mg_per_ml", f.bloodBilirubin_mgPerMl},
           {"blood beta_carotene_mg_per_ml", f.bloodBetaCarotene_mgPerMl},
           {"stratum corneum beta_carotene_mg_per_ml", f.stratumCorneumBetaCarotene_mgPerMl},
           {"epidermis beta_carotene_mg_per_ml", f.epidermisBetaCarotene_mgPerMl},
           {"stratum corneum urocanic_acid_mol_per_l", f.stratumCorneumUrocanicAcid_molPerL},
           {"skin_dna_mg_per_ml", f.dna_mgPerMl}})
    checkValue(s, what, value, kNonNegative);
}

}  // namespace hylios::skin
