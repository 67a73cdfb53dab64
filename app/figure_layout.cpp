#include "app/figure_layout.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>

#include "renderer/image/film_output.h"

namespace hylios {
namespace {

/// "7", "1.5", "0.002": the shortest text that reads back as the number (up to 6 digits).
std::string number(double value) { return fmt::format("{:.6g}", value); }

struct OverrideName {
  const char* key;
  const char* label;
  const char* unit;  ///< "" for none
};
/// Caption names of the scene-wide override keys (skin/specimen.h). "Epidermal melanin" is the
/// figure scenes' reading of melanosome_percent (docs/scene-format.md, "The figure scenes").
constexpr OverrideName kOverrideNames[] = {
    {"melanosome_percent", "epidermal melanin", "%"},
    {"colloidal_melanin_percent", "colloidal melanin", "%"},
    {"blood_percent", "dermal blood", "%"},
    {"oxygenation_percent", "oxygenation", "%"},
    {"surface_fold_aspect_ratio", "surface fold aspect ratio", ""},
    {"melanosome_eumelanin_mg_per_ml", "eumelanin", "mg/ml"},
    {"melanosome_pheomelanin_mg_per_ml", "pheomelanin", "mg/ml"},
};

/// "stratum_basale" → "stratum basale".
std::string spaced(std::string text) {
  std::replace(text.begin(), text.end(), '_', ' ');
  return text;
}

std::string withUnit(const std::string& label, double value, const std::string& unit) {
  if (unit.empty()) return label + " " + number(value);
  return label + " " + number(value) + " " + unit;
}

constexpr const char* kWaterKey = "water_reduction_percent";

/// The quantities of one skin material; `prefix` names the material when a scene has several.
void skinQuantities(const MaterialDesc& material, const std::string& prefix,
                    std::vector<SceneQuantity>& out) {
  const SkinMaterialDesc& skin = material.skin;
  const std::string key = "skin:" + material.name + "/";
  out.push_back({key + "specimen", std::nullopt, prefix + "specimen " + skin.specimen});
  // The last value of each key wins (the parser applies them in file order).
  std::vector<std::string> keys;
  std::map<std::string, double> values;
  for (const auto& o : skin.overrides) {
    if (!values.count(o.key)) keys.push_back(o.key);
    values[o.key] = o.value;
  }
  for (const std::string& k : keys) {
    if (k == kWaterKey) continue;  // with the material's own reduction below
    out.push_back({key + k, values[k], prefix + overrideText(k, values[k])});
  }
  // Water: the specimen's reduction (override) and the material's, combined as the model does.
  const double specimenReduction = values.count(kWaterKey) ? values[kWaterKey] / 100 : 0.0;
  const double reductionPercent = 100 * (1 - (1 - specimenReduction) * (1 - skin.waterReduction));
  out.push_back(
      {key + "water", reductionPercent, prefix + overrideText(kWaterKey, reductionPercent)});
  const double freckles = skin.freckles.densityPerCm2;
  out.push_back({key + "freckles", freckles,
                 prefix + (freckles > 0 ? "freckles " + number(freckles) + " /cm²"
                                        : std::string("no freckles"))});
  if (!skin.melaninMap.empty())
    out.push_back({key + "melanin_map", std::nullopt,
                   prefix + "melanin map " + skin.melaninMap.filename().string()});
}

/// Orders two values of one quantity: a missing value first, then numbers, then texts.
int compareValues(const SceneQuantity* a, const SceneQuantity* b) {
  if (!a || !b) return (a ? 1 : 0) - (b ? 1 : 0);
  if (a->number && b->number) return (*a->number > *b->number) - (*a->number < *b->number);
  if (a->number || b->number) return a->number ? -1 : 1;
  return a->text.compare(b->text);
}

bool sameValue(const SceneQuantity* a, const SceneQuantity* b) {
  if (!a || !b) return !a && !b;
  return a->text == b->text && a->number == b->number;
}

const SceneQuantity* find(const std::vector<SceneQuantity>& quantities, const std::string& key) {
  for (const SceneQuantity& q : quantities)
    if (q.key == key) return &q;
  return nullptr;
}

/// "epidermal melanin as S1": the caption of an override a scene leaves to its specimen.
std::string missingText(const SceneDesc& scene, const std::string& key) {
  const std::string name = key.substr(key.rfind('/') + 1);
  std::string specimen = "its specimen";
  for (const MaterialDesc& m : scene.materials)
    if (m.kind == MaterialDesc::Kind::Skin && key.rfind("skin:" + m.name + "/", 0) == 0)
      specimen = m.skin.specimen;
  const std::string text = overrideText(name, 0);
  const auto labelEnd = text.find(" 0");
  return (labelEnd == std::string::npos ? name : text.substr(0, labelEnd)) + " as " + specimen;
}

bool endsWith(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

std::string join(const std::vector<std::string>& parts, const char* separator) {
  std::string text;
  for (const std::string& p : parts) text += (text.empty() ? "" : separator) + p;
  return text;
}

}  // namespace

std::string bandText(const BandDesc& band) {
  if (!band.isRange()) return number(band.minNm) + " nm";
  const std::string span = number(band.minNm) + "–" + number(band.maxNm) + " nm";
  return isColourBand(band) ? "visible " + span : span;
}

std::string overrideText(const std::string& key, double value) {
  if (key == kWaterKey)  // the paper's Fig. 14: "No reduction", "20% reduction", …
    return value == 0 ? "no water reduction" : "water −" + number(value) + " %";
  for (const OverrideName& n : kOverrideNames)
    if (key == n.key) return withUnit(n.label, value, n.unit);
  // Layer-qualified keys: "stratum_basale.thickness_cm" → "stratum basale thickness 0.002 cm".
  if (const auto dot = key.find('.'); dot != std::string::npos) {
    const std::string layer = spaced(key.substr(0, dot)), what = key.substr(dot + 1);
    if (what == "thickness_cm") return withUnit(layer + " thickness", value, "cm");
    if (what == "melanosome_percent") return withUnit(layer + " melanosomes", value, "%");
    if (what == "colloidal_melanin_percent")
      return withUnit(layer + " colloidal melanin", value, "%");
    if (what == "blood_percent") return withUnit(layer + " blood", value, "%");
  }
  return key + " = " + number(value);
}

std::vector<SceneQuantity> sceneQuantities(const SceneDesc& scene) {
  std::vector<SceneQuantity> out;
  const auto& bands = scene.film.bands;
  for (std::size_t b = 0; b < bands.size(); ++b)
    out.push_back({b == 0 ? std::string("band") : fmt::format("band#{}", b + 1), bands[b].minNm,
                   bandText(bands[b])});
  std::size_t skins = 0;
  for (const MaterialDesc& m : scene.materials) skins += m.kind == MaterialDesc::Kind::Skin;
  for (const MaterialDesc& m : scene.materials)
    if (m.kind == MaterialDesc::Kind::Skin)
      skinQuantities(m, skins > 1 ? m.name + ": " : std::string(), out);
  return out;
}

FigureLayout layoutFigure(const std::vector<SceneDesc>& scenes) {
  if (scenes.empty()) throw std::invalid_argument("a figure needs at least one scene");
  std::vector<std::vector<SceneQuantity>> quantities;
  bool multiBand = false;
  for (const SceneDesc& s : scenes) {
    quantities.push_back(sceneQuantities(s));
    multiBand = multiBand || s.film.bands.size() > 1;
  }
  // Every key, in the order of first appearance (the first scene's first).
  std::vector<std::string> keys;
  std::set<std::string> seen;
  for (const auto& list : quantities)
    for (const SceneQuantity& q : list)
      if (seen.insert(q.key).second) keys.push_back(q.key);
  FigureLayout layout;
  layout.bandInCaptions = multiBand;
  std::vector<std::string> shared;
  for (const std::string& key : keys) {
    const bool isBand = key.rfind("band", 0) == 0;
    if (isBand && multiBand) continue;  // named per panel instead
    bool varies = false;
    for (const auto& list : quantities)
      varies = varies || !sameValue(find(list, key), find(quantities[0], key));
    if (varies) {
      layout.varied.push_back(key);
      layout.bandInCaptions = layout.bandInCaptions || isBand;
      continue;
    }
    const SceneQuantity* q = find(quantities[0], key);
    // Defaults that say nothing (no dehydration, no freckles) stay out of the title.
    const bool silent =
        q->number && *q->number == 0 && (endsWith(key, "/water") || endsWith(key, "/freckles"));
    if (!silent) shared.push_back(q->text);
  }
  layout.title = join(shared, " · ");
  layout.order.resize(scenes.size());
  for (std::size_t i = 0; i < scenes.size(); ++i) layout.order[i] = i;
  std::stable_sort(layout.order.begin(), layout.order.end(), [&](std::size_t a, std::size_t b) {
    for (const std::string& key : layout.varied) {
      const int c = compareValues(find(quantities[a], key), find(quantities[b], key));
      if (c != 0) return c < 0;
    }
    return false;
  });
  for (const std::size_t i : layout.order) {
    std::vector<std::string> parts;
    for (const std::string& key : layout.varied) {
      const SceneQuantity* q = find(quantities[i], key);
      parts.push_back(q ? q->text : missingText(scenes[i], key));
    }
    if (parts.empty() && scenes.size() > 1) parts.push_back(scenes[i].file.stem().string());
    layout.captions.push_back(join(parts, ", "));
  }
  return layout;
}

}  // namespace hylios
