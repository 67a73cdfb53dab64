// Scene files: the TOML layout documented in docs/scene-format.md, read table by table with
// TomlTableReader (renderer/scene/toml_table_reader.h), then cross-checked (names, spectra ×
// bands).
#include "renderer/scene/scene_file.h"

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include "renderer/scene/data_paths.h"
#include "renderer/scene/scene_spectrum_reader.h"
#include "renderer/scene/toml_table_reader.h"
#include "skin/core/toml_location.h"
#include "skin/spectral_database.h"

namespace hylios {

const std::map<std::string, std::vector<std::string>>& sceneFileKeys() {
  static const std::map<std::string, std::vector<std::string>> keys = {
      {"camera", {"position", "look_at", "up", "fov_deg", "aperture_radius", "focus_distance"}},
      {"film", {"resolution", "spp", "exposure", "band"}},
      {"film.band", {"name", "wavelength_nm", "preview_range", "range_nm", "step_nm"}},
      {"integrator",
       {"max_depth", "seed", "skin_mode", "effect_tolerance", "estimator", "noise_target",
        "sampler", "exit_control_variate", "table_rays_per_bin"}},
      {"light",
       {"type", "emission", "position", "direction", "inner_angle_deg", "outer_angle_deg", "shape",
        "camera_visible"}},
      {"material",
       {"name", "type", "specimen", "overrides", "freckles", "melanin_map",
        "water_reduction_percent", "reflectance", "refractive_index", "roughness"}},
      {"material.freckles", {"density_per_cm2", "radius_cm", "melanin_gain", "seed"}},
      {"material.melanin_map", {"file", "min_multiplier", "max_multiplier"}},
      {"shape",
       {"name", "type", "material", "file", "smooth_normals", "transform", "centre", "radius",
        "point", "normal", "size"}},
      {"shape.transform", {"translate", "rotate_deg", "scale"}},
      {"top level", {"unit_cm", "camera", "film", "light", "material", "shape", "integrator"}},
  };
  return keys;
}

namespace {

using Reader = TomlTableReader;

/// The reader of element #index of the array of tables `name` ([[name]]), with its keys.
Reader elementReader(const toml::table& t, const std::string& name, int index,
                     const TomlSource& src) {
  return Reader(t, fmt::format("[[{}]] #{}", name, index), src, sceneFileKeys().at(name));
}

constexpr std::int64_t kMaxResolution = kMaxFilmSide;
constexpr std::int64_t kMaxPixels = kMaxFilmPixels;
constexpr std::int64_t kMaxSamplesPerPixel = 1000000;
constexpr std::size_t kMaxChannelsPerBand = 2251;  // 250–2500 nm at 1 nm
const NumberRange kSpectralNm =
    NumberRange::closed(skin::kModelMinWavelengthNm, skin::kModelMaxWavelengthNm);
const NumberRange kPercent = NumberRange::closed(0, 100);
// One scene unit is between 10 nm and 10 km: the skin walk's offsets (cm) divided by unit_cm stay
// within the scene extent limit (kMaxSceneCoordinate).
constexpr double kMinUnitCm = 1e-6;
constexpr double kMaxUnitCm = 1e6;

/// The elements of `[[key]]` in `reader`'s table (none if absent).
std::vector<const toml::table*> arrayOfTables(Reader& reader, const std::string& key,
                                              const std::string& spelled) {
  const toml::node* n = reader.node(key);
  if (!n) return {};
  const toml::array* array = n->as_array();
  if (!array || array->empty() || !array->is_array_of_tables())
    reader.fail(*n, fmt::format("'{}' must be an array of tables, written {}", key, spelled));
  std::vector<const toml::table*> tables;
  for (const toml::node& element : *array) tables.push_back(element.as_table());
  return tables;
}

/// Remembers where each name was defined, to refuse a second definition.
class NameRegistry {
 public:
  explicit NameRegistry(std::string what) : what_(std::move(what)) {}
  void add(const std::string& name, const SourceLocation& where) {
    const auto [it, inserted] = where_.emplace(name, where);
    if (!inserted)
      throw SceneError(where, fmt::format("duplicate {} name '{}' (first defined at {})", what_,
                                          name, it->second.str()));
  }
  bool contains(const std::string& name) const { return where_.count(name) != 0; }
  std::string list() const {
    std::string text;
    for (const auto& [name, where] : where_) text += (text.empty() ? "'" : ", '") + name + "'";
    return text.empty() ? "none" : text;
  }

 private:
  std::string what_;
  std::map<std::string, SourceLocation> where_;
};

/// Where `name = ...` of an element is (the element itself when it has none).
SourceLocation nameLocation(const toml::table& t, const TomlSource& src) {
  const toml::node* name = t.get("name");
  return locationOf(src, name ? *name : static_cast<const toml::node&>(t));
}

// ---- camera, film, integrator ---------------------------------------------------------------

CameraDesc readCamera(const toml::table& t, const TomlSource& src) {
  Reader r(t, "[camera]", src, sceneFileKeys().at("camera"));
  CameraDesc c;
  c.where = r.where();
  c.position = r.vec3("position");
  c.lookAt = r.vec3("look_at");
  c.up = r.vec3("up", {0, 1, 0});
  c.verticalFovDeg = r.number("fov_deg", {0, 180, true, true}, 40);
  c.apertureRadius = r.number("aperture_radius", sceneLengthRange(), 0);
  c.focusDistance = r.number("focus_distance", sceneLengthRange(), 0);
  const glm::dvec3 view = c.lookAt - c.position;
  if (glm::length(view) == 0)
    throw SceneError(r.whereValue("look_at"), "'look_at' equals 'position'");
  if (glm::length(glm::cross(glm::normalize(view), c.up)) <= 1e-9 * glm::length(c.up) ||
      glm::length(c.up) == 0)
    throw SceneError(r.whereValue("up"), "'up' is zero or parallel to the viewing direction");
  r.finish("[camera]");
  return c;
}

bool isChannelName(const std::string& name) {
  if (name.empty()) return false;
  for (char ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '_' && ch != '-') return false;
  return true;
}

BandDesc readBand(const toml::table& t, int index, const TomlSource& src) {
  Reader r = elementReader(t, "film.band", index, src);
  BandDesc b;
  b.where = r.where();
  b.name = r.string("name");
  if (!isChannelName(b.name))
    throw SceneError(r.whereValue("name"),
                     fmt::format("band name '{}' must be letters, digits, '_' or '-'", b.name));
  if (r.has("wavelength_nm") && r.has("range_nm"))
    throw SceneError(r.whereValue("range_nm"),
                     "a band has either 'wavelength_nm' (one "
                     "wavelength) or 'range_nm' (a range), not both");
  if (r.has("wavelength_nm")) {
    b.minNm = b.maxNm = r.number("wavelength_nm", kSpectralNm);
    if (r.has("preview_range")) {
      const std::vector<double> p = r.numbers("preview_range", 2, NumberRange::any());
      if (!(p[0] < p[1]))
        throw SceneError(r.whereValue("preview_range"), "'preview_range' must ascend");
      b.previewMin = p[0];
      b.previewMax = p[1];
    }
    r.finish("a single-wavelength band");
  } else if (r.has("range_nm")) {
    const std::vector<double> range = r.numbers("range_nm", 2, kSpectralNm);
    if (!(range[0] < range[1]))
      throw SceneError(r.whereValue("range_nm"), "'range_nm' must ascend");
    b.minNm = range[0];
    b.maxNm = range[1];
    b.stepNm = r.number("step_nm", {0, b.maxNm - b.minNm, true, false});
    if (b.channelWavelengths().size() > kMaxChannelsPerBand)
      throw SceneError(r.whereValue("step_nm"),
                       fmt::format("'step_nm' = {} gives {} channels; at most {}", b.stepNm,
                                   b.channelWavelengths().size(), kMaxChannelsPerBand));
    r.finish("a range band ('preview_range' is for single-wavelength bands)");
  } else {
    r.failHere("a band needs 'wavelength_nm' (one wavelength) or 'range_nm' and 'step_nm'");
  }
  return b;
}

/// Two channels whose wavelengths round to the same 1e-6 nm would share a spectral EXR channel
/// name (S0.<λ to 6 decimals>nm, renderer/image/film_output.h): refused, naming both bands.
void checkDistinctChannels(const FilmDesc& film) {
  std::map<long long, std::pair<std::size_t, double>> seen;  // λ in 1e-6 nm -> band, λ
  for (std::size_t b = 0; b < film.bands.size(); ++b) {
    for (double nm : film.bands[b].channelWavelengths()) {
      const long long key = std::llround(nm * 1e6);
      const auto [it, inserted] = seen.emplace(key, std::make_pair(b, nm));
      if (inserted) continue;
      const BandDesc& first = film.bands[it->second.first];
      throw SceneError(
          film.bands[b].where,
          fmt::format("band '{}' has a channel at {} nm and band '{}' (at {}) one at {} nm: the "
                      "spectral channels would share one name (wavelengths are kept to 1e-6 nm); "
                      "give each channel its own wavelength",
                      film.bands[b].name, nm, first.name, first.where.str(), it->second.second));
    }
  }
}

FilmDesc readFilm(const toml::table& t, const TomlSource& src) {
  Reader r(t, "[film]", src, sceneFileKeys().at("film"));
  FilmDesc f;
  f.where = r.where();
  const toml::node* res = r.node("resolution");
  if (!res) r.failHere("missing key 'resolution' in [film]");
  const toml::array* wh = res->as_array();
  if (!wh || wh->size() != 2 || !wh->get(0)->is_integer() || !wh->get(1)->is_integer())
    r.fail(*res, "'resolution' must be an array of two integers [width, height]");
  const std::int64_t w = *wh->get(0)->value<std::int64_t>();
  const std::int64_t h = *wh->get(1)->value<std::int64_t>();
  for (std::int64_t v : {w, h})
    if (v < 1 || v > kMaxResolution)
      r.fail(*res,
             fmt::format("'resolution' = [{}, {}]: each must be in [1, {}]", w, h, kMaxResolution));
  if (w * h > kMaxPixels)
    r.fail(*res, fmt::format("'resolution' = [{}, {}] is {} pixels; at most {} (64 Mpixel)", w, h,
                             w * h, kMaxPixels));
  f.width = static_cast<int>(w);
  f.height = static_cast<int>(h);
  f.samplesPerPixel = static_cast<int>(r.integer("spp", 1, kMaxSamplesPerPixel));
  f.exposure = r.number("exposure", NumberRange::closed(1e-6, 1e6), 1.0);
  NameRegistry names("band");
  int index = 0;
  for (const toml::table* band : arrayOfTables(r, "band", "[[film.band]]")) {
    f.bands.push_back(readBand(*band, ++index, src));
    names.add(f.bands.back().name, nameLocation(*band, src));
  }
  if (f.bands.empty()) r.failHere("[film] needs at least one [[film.band]]");
  checkDistinctChannels(f);
  r.finish("[film]");
  return f;
}

IntegratorDesc readIntegrator(const toml::table* t, const TomlSource& src) {
  IntegratorDesc d;
  if (!t) return d;
  Reader r(*t, "[integrator]", src, sceneFileKeys().at("integrator"));
  d.where = r.where();
  d.maxDepth = static_cast<int>(r.integer("max_depth", 1, 1024, d.maxDepth));
  d.seed =
      static_cast<std::uint64_t>(r.integer("seed", 0, std::numeric_limits<std::int64_t>::max(), 1));
  if (r.has("skin_mode"))
    d.skinMode =
        *findEnum(r.choice("skin_mode", enumNameList(skin::kSkinModeNames)), skin::kSkinModeNames);
  d.effectTolerance =
      r.number("effect_tolerance", NumberRange::closed(0.0, 1.0), d.effectTolerance);
  if (r.has("estimator"))
    d.estimator = *skin::parseEstimator(r.choice("estimator", {"spectral", "per-wavelength"}));
  if (r.has("noise_target"))
    d.noiseTarget = r.number("noise_target", NumberRange::closed(1e-6, 10.0));
  if (r.has("sampler"))
    d.sampler = *findEnum(r.choice("sampler", enumNameList(kSamplerNames)), kSamplerNames);
  d.exitControlVariate = r.boolean("exit_control_variate", d.exitControlVariate);
  d.tableRaysPerBin = static_cast<std::uint64_t>(r.integer(
      "table_rays_per_bin", 1000, 10000000, static_cast<std::int64_t>(d.tableRaysPerBin)));
  r.finish("[integrator]");
  return d;
}

// ---- lights ---------------------------------------------------------------------------------

LightDesc readLight(const toml::table& t, int index, const TomlSource& src,
                    const NameRegistry& shapes) {
  Reader r = elementReader(t, "light", index, src);
  LightDesc l;
  l.where = r.where();
  const std::string type = r.choice("type", {"point", "spot", "area", "environment"});
  l.emission = readEmission(r);
  if (type == "point" || type == "spot") {
    l.kind = type == "point" ? LightDesc::Kind::Point : LightDesc::Kind::Spot;
    l.position = r.vec3("position");
  }
  if (type == "spot") {
    const glm::dvec3 direction = r.vec3("direction");
    if (glm::length(direction) == 0)
      throw SceneError(r.whereValue("direction"), "'direction' must not be zero");
    l.direction = glm::normalize(direction);
    l.spotOuterDeg = r.number("outer_angle_deg", {0, 90, true, false});
    l.spotInnerDeg = r.number("inner_angle_deg", {0, l.spotOuterDeg}, l.spotOuterDeg);
  }
  if (type == "area") {
    l.kind = LightDesc::Kind::Area;
    l.shape = r.string("shape");
    if (!shapes.contains(l.shape))
      throw SceneError(r.whereValue("shape"), fmt::format("unknown shape '{}' (named shapes: {})",
                                                          l.shape, shapes.list()));
  }
  if (type == "environment") {
    l.kind = LightDesc::Kind::Environment;
    l.cameraVisible = r.boolean("camera_visible", true);
  }
  r.finish(fmt::format("a \"{}\" light", type));
  return l;
}

// ---- materials ------------------------------------------------------------------------------

struct PositionedOverride {
  skin::SpecimenOverride value;
  SourceLocation where;  ///< the key's position
};

/// Leaves of `table` with dotted keys: `a.b = 1` and `"a.b" = 1` give the same override.
void flattenOverrides(const toml::table& table, const std::string& prefix, const Reader& r,
                      std::vector<PositionedOverride>& out) {
  for (auto&& [key, value] : table) {
    const std::string name = prefix + std::string(key.str());
    if (const toml::table* nested = value.as_table()) {
      flattenOverrides(*nested, name + ".", r, out);
      continue;
    }
    const SourceLocation at = skin::tomlSourceLocation(r.source().name, key.source());
    const double number = r.toNumber(value, "override '" + name + "'", NumberRange::any());
    out.push_back({{name, number, at.str()}, at});
  }
}

/// Loads the specimen and applies the overrides, so that every error shows at parse time.
void checkSpecimen(Reader& r, const SkinMaterialDesc& skin,
                   const std::vector<PositionedOverride>& overrides) {
  skin::Specimen specimen;
  try {
    specimen = skin::loadSpecimen(skin.specimen, specimenDir());
  } catch (const std::exception& error) {
    throw SceneError(r.whereValue("specimen"),
                     fmt::format("specimen '{}': {}", skin.specimen, error.what()));
  }
  for (const PositionedOverride& o : overrides) {
    try {
      skin::applyOverride(specimen, o.value);
    } catch (const skin::SpecimenError& error) {
      std::string text = error.what();
      const std::string prefix = o.value.origin + ": ";
      if (text.rfind(prefix, 0) == 0) text = text.substr(prefix.size());
      throw SceneError(o.where, text);
    }
  }
  try {
    skin::validateSpecimen(specimen);
  } catch (const skin::SpecimenError& error) {
    throw SceneError(r.whereValue("overrides"),
                     fmt::format("specimen after the overrides: {}", error.what()));
  }
}

/// "S1" … names a file in scenes/specimens/; anything with a '/' or ending in .toml is a path
/// relative to the scene file, stored resolved.
std::string readSpecimenName(Reader& r) {
  const std::string text = r.string("specimen");
  if (text.empty()) throw SceneError(r.whereValue("specimen"), "'specimen' must not be empty");
  const bool isPath =
      text.find('/') != std::string::npos || std::filesystem::path(text).extension() == ".toml";
  return isPath ? r.existingFile("specimen").string() : text;
}

SkinMaterialDesc readSkin(Reader& r) {
  SkinMaterialDesc skin;
  skin.specimen = readSpecimenName(r);
  std::vector<PositionedOverride> overrides;
  if (const toml::table* t = r.table("overrides")) flattenOverrides(*t, "", r, overrides);
  // toml++ iterates keys sorted; apply them in the order the file gives them.
  std::stable_sort(overrides.begin(), overrides.end(), [](const auto& a, const auto& b) {
    return std::make_pair(a.where.line, a.where.column) <
           std::make_pair(b.where.line, b.where.column);
  });
  for (const auto& o : overrides) skin.overrides.push_back(o.value);
  if (const toml::table* t = r.table("freckles")) {
    Reader f(*t, r.label() + " freckles", r.source(), sceneFileKeys().at("material.freckles"));
    // Bounded (issue 13): a density of 1e300 per cm² would make the freckle field without end.
    skin.freckles.densityPerCm2 = f.number("density_per_cm2", NumberRange::closed(0, 1e4));
    skin.freckles.radiusCm = f.number("radius_cm", NumberRange::closed(1e-4, 10), 0.15);
    skin.freckles.melaninGain = f.number("melanin_gain", {0, 1e3, true, false}, 3);
    skin.freckles.seed = static_cast<std::uint64_t>(
        f.integer("seed", 0, std::numeric_limits<std::int64_t>::max(), 1));
    f.finish("'freckles'");
  }
  if (const toml::table* t = r.table("melanin_map")) {
    Reader m(*t, r.label() + " melanin_map", r.source(),
             sceneFileKeys().at("material.melanin_map"));
    skin.melaninMap = m.existingFile("file");
    skin.melaninMapMin = m.number("min_multiplier", NumberRange::closed(0, 1e3));
    skin.melaninMapMax = m.number("max_multiplier", NumberRange::closed(0, 1e3));
    m.finish("'melanin_map'");
  }
  skin.waterReduction = r.number("water_reduction_percent", kPercent, 0) / 100;
  checkSpecimen(r, skin, overrides);
  return skin;
}

MaterialDesc readMaterial(const toml::table& t, int index, const TomlSource& src) {
  Reader r = elementReader(t, "material", index, src);
  MaterialDesc m;
  m.where = r.where();
  m.name = r.nonEmptyString("name");
  const std::string type = r.choice("type", {"skin", "diffuse", "dielectric"});
  if (type == "skin") {
    m.kind = MaterialDesc::Kind::Skin;
    m.skin = readSkin(r);
  }
  if (type == "diffuse") {
    m.kind = MaterialDesc::Kind::Diffuse;
    m.reflectance = readReflectance(r);
  }
  if (type == "dielectric") {
    m.kind = MaterialDesc::Kind::Dielectric;
    m.refractiveIndex = r.number("refractive_index", NumberRange::closed(1, 10), 1.5);
    m.roughness = r.number("roughness", NumberRange::closed(0, 1), 0);
  }
  r.finish(fmt::format("a \"{}\" material", type));
  return m;
}

// ---- shapes ---------------------------------------------------------------------------------

/// translate · Rz · Ry · Rx · scale: scale first, then rotate about x, y, z (fixed axes), then
/// translate.
glm::dmat4 readTransform(const toml::table& t, const std::string& label, const TomlSource& src) {
  Reader r(t, label, src, sceneFileKeys().at("shape.transform"));
  const glm::dvec3 translate = r.vec3("translate", glm::dvec3(0));
  const glm::dvec3 rotateDeg = r.vec3("rotate_deg", glm::dvec3(0));
  glm::dvec3 scale(1);
  if (const toml::node* s = t.get("scale"); s && s->is_array()) {
    const std::vector<double> v = r.numbers("scale", 3, sceneSizeRange());
    scale = {v[0], v[1], v[2]};
  } else if (s) {
    scale = glm::dvec3(r.number("scale", sceneSizeRange()));
  }
  r.finish("'transform'");
  glm::dmat4 m = glm::translate(glm::dmat4(1.0), translate);
  m = glm::rotate(m, glm::radians(rotateDeg.z), glm::dvec3(0, 0, 1));
  m = glm::rotate(m, glm::radians(rotateDeg.y), glm::dvec3(0, 1, 0));
  m = glm::rotate(m, glm::radians(rotateDeg.x), glm::dvec3(1, 0, 0));
  return glm::scale(m, scale);
}

ShapeDesc readShape(const toml::table& t, int index, const TomlSource& src,
                    const NameRegistry& materials) {
  Reader r = elementReader(t, "shape", index, src);
  ShapeDesc s;
  s.where = r.where();
  if (r.has("name")) s.name = r.nonEmptyString("name");
  const std::string type = r.choice("type", {"mesh", "sphere", "plane"});
  s.material = r.string("material");
  if (!materials.contains(s.material))
    throw SceneError(r.whereValue("material"), fmt::format("unknown material '{}' (materials: {})",
                                                           s.material, materials.list()));
  if (type == "mesh") {
    s.kind = ShapeDesc::Kind::Mesh;
    s.meshPath = r.existingFile("file");
    s.smoothNormals = r.boolean("smooth_normals", true);
    if (const toml::table* transform = r.table("transform"))
      s.transform = readTransform(*transform, r.label() + " transform", src);
  }
  if (type == "sphere") {
    s.kind = ShapeDesc::Kind::Sphere;
    s.centre = r.vec3("centre", glm::dvec3(0));
    s.radius = r.number("radius", sceneSizeRange());
  }
  if (type == "plane") {
    s.kind = ShapeDesc::Kind::Plane;
    s.planePoint = r.vec3("point", glm::dvec3(0));
    const glm::dvec3 normal = r.vec3("normal", {0, 1, 0});
    if (glm::length(normal) == 0)
      throw SceneError(r.whereValue("normal"), "'normal' must not be zero");
    s.planeNormal = glm::normalize(normal);
    s.planeSize = r.number("size", sceneSizeRange(), 10);
  }
  r.finish(fmt::format("a \"{}\" shape", type));
  return s;
}

// ---- the whole scene ------------------------------------------------------------------------

const toml::table& requiredTable(Reader& root, const std::string& key) {
  const toml::table* t = root.table(key);
  if (!t) root.failHere(fmt::format("missing table [{}]", key));
  return *t;
}

std::vector<LightDesc> readLights(Reader& root, const TomlSource& src, const NameRegistry& shapes) {
  std::vector<LightDesc> lights;
  std::map<std::string, SourceLocation> areaShapes;
  const LightDesc* environment = nullptr;
  int index = 0;
  for (const toml::table* t : arrayOfTables(root, "light", "[[light]]")) {
    lights.push_back(readLight(*t, ++index, src, shapes));
    const LightDesc& l = lights.back();
    if (l.kind == LightDesc::Kind::Environment && environment)
      throw SceneError(l.where, fmt::format("a second environment light (the first is at {})",
                                            environment->where.str()));
    if (l.kind == LightDesc::Kind::Environment) environment = &l;
    if (l.kind == LightDesc::Kind::Area && !areaShapes.emplace(l.shape, l.where).second)
      throw SceneError(l.where, fmt::format("shape '{}' already emits (area light at {})", l.shape,
                                            areaShapes[l.shape].str()));
  }
  if (lights.empty()) root.failHere("a scene needs at least one [[light]]");
  return lights;
}

SceneDesc parseRoot(const toml::table& rootTable, const TomlSource& src) {
  Reader root(rootTable, "the top level", src, sceneFileKeys().at("top level"));
  SceneDesc scene;
  scene.unitCm = root.number("unit_cm", NumberRange::closed(kMinUnitCm, kMaxUnitCm), 1.0);
  scene.camera = readCamera(requiredTable(root, "camera"), src);
  scene.film = readFilm(requiredTable(root, "film"), src);
  NameRegistry materials("material");
  int index = 0;
  for (const toml::table* t : arrayOfTables(root, "material", "[[material]]")) {
    scene.materials.push_back(readMaterial(*t, ++index, src));
    materials.add(scene.materials.back().name, nameLocation(*t, src));
  }
  NameRegistry shapes("shape");
  index = 0;
  for (const toml::table* t : arrayOfTables(root, "shape", "[[shape]]")) {
    scene.shapes.push_back(readShape(*t, ++index, src, materials));
    if (!scene.shapes.back().name.empty())
      shapes.add(scene.shapes.back().name, nameLocation(*t, src));
  }
  scene.lights = readLights(root, src, shapes);
  scene.integrator = readIntegrator(root.table("integrator"), src);
  root.finish("the top level");
  for (const LightDesc& light : scene.lights) checkCoversBands(light.emission, scene.film);
  for (const MaterialDesc& m : scene.materials)
    if (m.kind == MaterialDesc::Kind::Diffuse) checkCoversBands(m.reflectance, scene.film);
  return scene;
}

}  // namespace

SceneDesc parseSceneText(const std::string& tomlText, const std::string& sourceName,
                         const std::filesystem::path& baseDir) {
  toml::table root;
  try {
    root = toml::parse(tomlText, sourceName);
  } catch (const toml::parse_error& error) {
    throw SceneError(skin::tomlSourceLocation(sourceName, error.source()),
                     std::string(error.description()));
  }
  SceneDesc scene = parseRoot(root, {sourceName, baseDir});
  scene.file = sourceName;
  return scene;
}

SceneDesc loadSceneFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw SceneError({path.string(), 1, 1}, "cannot open the scene file");
  std::stringstream text;
  text << in.rdbuf();
  const std::filesystem::path baseDir =
      path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  SceneDesc scene = parseSceneText(text.str(), path.string(), baseDir);
  scene.file = path;
  return scene;
}

}  // namespace hylios
