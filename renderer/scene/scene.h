// A parsed, validated scene: what the scene file (renderer/scene/scene_file.h) says, in plain
// structs. Every element keeps the file position it came from, so later errors (a missing mesh, a
// malformed OBJ, a bad texture) still name file:line:col.
//
// Units: scene lengths are in scene units; `unitCm` says how many centimetres one unit is (the
// head mesh is about 5 cm per unit). Wavelengths in nm. Radiance in W·m⁻²·sr⁻¹·nm⁻¹ (relative).
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "renderer/scene/sampler_kind.h"
#include "skin/core/source_location.h"
#include "skin/effect_plan.h"
#include "skin/estimator.h"
#include "skin/skin_mode.h"
#include "skin/specimen.h"

namespace hylios {

/// Any error in a scene or in what it refers to; what() reads "file:line:col: message".
class SceneError : public std::runtime_error {
 public:
  SceneError(const SourceLocation& where, const std::string& message)
      : std::runtime_error(where.str() + ": " + message), where_(where) {}
  const SourceLocation& where() const { return where_; }

 private:
  SourceLocation where_;
};

struct CameraDesc {
  glm::dvec3 position{0, 0, 5};
  glm::dvec3 lookAt{0, 0, 0};
  glm::dvec3 up{0, 1, 0};
  double verticalFovDeg = 40;
  double apertureRadius = 0;  ///< thin lens; 0 = pinhole
  double focusDistance = 0;   ///< 0 = distance to lookAt
  SourceLocation where;
};

/// One output band: a single wavelength (minNm == maxNm) or a range sampled at stepNm intervals
/// (one EXR channel per step), e.g. the visible 380–780 nm for the sRGB preview.
struct BandDesc {
  std::string name;
  double minNm = 0;
  double maxNm = 0;
  double stepNm = 0;  ///< range bands only
  /// Fixed pseudo-colour scale for single-wavelength previews (so a series compares).
  double previewMin = 0;
  double previewMax = 1;
  SourceLocation where;
  bool isRange() const { return maxNm > minNm; }
  /// The channel wavelengths this band writes.
  std::vector<double> channelWavelengths() const;
};

struct FilmDesc {
  int width = 256;
  int height = 256;
  int samplesPerPixel = 16;
  std::vector<BandDesc> bands;
  double exposure = 1.0;  ///< scale applied before the sRGB transfer of the visible preview
  SourceLocation where;
};

/// An emission spectrum (relative spectral radiance), evaluated per wavelength.
struct EmissionDesc {
  enum class Kind { Constant, D65, Blackbody, Led, Tabulated } kind = Kind::Constant;
  double scale = 1;                                   ///< multiplies the shape
  double temperatureK = 0;                            ///< Blackbody (normalised to 1 at its peak)
  double centreNm = 0;                                ///< Led: Gaussian centre
  double fwhmNm = 0;                                  ///< Led: full width at half maximum
  std::vector<double> tableWavelengthNm, tableValue;  ///< Tabulated (file or inline)
  SourceLocation where;
};

struct LightDesc {
  enum class Kind { Area, Point, Spot, Environment } kind = Kind::Point;
  EmissionDesc emission;
  glm::dvec3 position{0};
  glm::dvec3 direction{0, 0, -1};  ///< Spot: axis
  double spotInnerDeg = 0;
  double spotOuterDeg = 0;
  std::string shape;  ///< Area: name of the emitting shape
  /// Environment: whether camera rays that miss every shape see it. false: black behind the
  /// subject (the paper's panels); it still lights the scene and is seen in reflections.
  bool cameraVisible = true;
  SourceLocation where;
};

/// Skin: a specimen plus overrides, and spatially varying inputs.
struct SkinMaterialDesc {
  std::string specimen = "S1";
  std::vector<skin::SpecimenOverride> overrides;
  std::filesystem::path
      melaninMap;            ///< optional greyscale texture in UV space: multiplier of melanin
  double melaninMapMin = 1;  ///< multiplier where the map is black
  double melaninMapMax = 1;  ///< multiplier where the map is white
  struct Freckles {
    double densityPerCm2 = 0;  ///< 0 = none
    double radiusCm = 0.15;
    double melaninGain = 3;  ///< melanin multiplier at a freckle's centre
    std::uint64_t seed = 1;
  } freckles;
  double waterReduction = 0;  ///< extra fraction in [0, 1], on top of the specimen's
};

struct MaterialDesc {
  enum class Kind { Skin, Diffuse, Dielectric } kind = Kind::Diffuse;
  std::string name;
  SkinMaterialDesc skin;
  EmissionDesc reflectance;      ///< Diffuse: reflectance spectrum in [0, 1]
  double refractiveIndex = 1.5;  ///< Dielectric
  double roughness = 0;          ///< Dielectric: 0 = smooth
  SourceLocation where;
};

struct ShapeDesc {
  enum class Kind { Mesh, Sphere, Plane } kind = Kind::Sphere;
  std::string name;
  std::filesystem::path meshPath;  ///< Mesh: OBJ, resolved against the scene file's folder
  glm::dmat4 transform{1.0};       ///< object to world (translate · rotate · scale)
  bool smoothNormals = true;
  glm::dvec3 centre{0};      ///< Sphere
  double radius = 1;         ///< Sphere
  glm::dvec3 planePoint{0};  ///< Plane (a square of side planeSize)
  glm::dvec3 planeNormal{0, 1, 0};
  double planeSize = 10;
  std::string material;  ///< name of a MaterialDesc
  SourceLocation where;
};

/// The render tables' rays per cosine bin unless a scene sets integrator.table_rays_per_bin:
/// 1–2 % sampling error of P(subsurface) per bin (SkinTableCache::renderSettings).
inline constexpr std::uint64_t kDefaultTableRaysPerBin = 10000;

struct IntegratorDesc {
  int maxDepth = 8;
  std::uint64_t seed = 1;
  skin::SkinMode skinMode =
      skin::SkinMode::Walk;  ///< exact walk at every hit, or exit tables (issue 5)
  double effectTolerance =
      skin::kDefaultEffectTolerance;  ///< ε of the effect planner (skin/effect_plan.h)
  /// spectral: a camera path carries every channel of a band (hero wavelengths) and skin hits run
  /// the spectral walk; per-wavelength: one channel per path and the analog walk (the reference).
  skin::Estimator estimator = skin::Estimator::Spectral;
  /// Render in passes until the film's estimated median per-pixel relative noise is at most this
  /// (every band, R, G, B and chromaticity), or spp is reached; unset: render spp samples.
  std::optional<double> noiseTarget;
  /// The camera paths' numbers (renderer/tracing/pixel_sampler.h).
  SamplerKind sampler = SamplerKind::Sobol;
  /// Table mode, spectral estimator: the exit point's control variate for the band's colour
  /// noise (renderer/tracing/integrator.h); false only to measure what it buys.
  bool exitControlVariate = true;
  /// Table mode: rays per cosine bin of every exit table (renderer/tracing/skin_table_cache.h);
  /// a table's sampling error, a fixed bias of the render, falls as 1/√rays.
  std::uint64_t tableRaysPerBin = kDefaultTableRaysPerBin;
  SourceLocation where;
};

struct SceneDesc {
  std::filesystem::path file;  ///< the scene file (relative paths resolve against its folder)
  double unitCm = 1;           ///< centimetres per scene unit
  CameraDesc camera;
  FilmDesc film;
  std::vector<LightDesc> lights;
  std::vector<MaterialDesc> materials;
  std::vector<ShapeDesc> shapes;
  IntegratorDesc integrator;
};

}  // namespace hylios
