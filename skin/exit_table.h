// Tabulated exit statistics of the HyLIoS walk (issue 5, the `table` skin mode): for one
// (SkinOptics, WalkOptions) the walk's outcome is tabulated once and then sampled at the cost of a
// few table look-ups instead of a whole random walk. A table is built either from analog walks of
// its own wavelength (build) or, for every wavelength of a bundle at once, from one set of spectral
// walks (buildBundle, skin/spectral_walk.h; issue 11).
//
// What is exact and what is tabulated. A ray from air first meets the rough surface; that step
// (SkinWalk::enterFromAir) is simulated exactly, so surface reflection (probability and direction)
// is the walk's own. A transmitted ray continues with direction t (t.z = μ_t > 0). By the symmetry
// of the plane-parallel stack about z, everything after entry depends on μ_t only, when the exit
// offset and exit direction are measured relative to t's azimuth φ_t. The table holds K bins at
// cosines μ_k = (k + 1)/K (the last at normal transmission, where most rays go); bin k is filled
// from N walks SkinWalk::traceEntered((√(1−μ_k²), 0, μ_k)), and a ray with μ_t between two centres
// uses the lower or upper bin with the linear-interpolation probabilities (one uniform number; μ_t
// < 1/K uses bin 0). Each bin keeps, as weights (an analog walk's path weighs 1 in its outcome; a
// spectral path weighs its exit weight at λ in its exit outcome and its absorbed weight per layer
// in the absorption outcomes, the weights of skin/spectral_walk.h, exact in expectation):
//   * outcome weights: subsurface exit, transmitted (truncated stacks), event limit, and absorbed
//     by layer, in a melanosome or not; an outcome is drawn with probability its weight over the
//     bin's total weight (for analog walks exactly the counted frequency; for spectral walks a
//     ratio estimate, whose O(1/N) bias is far below the table's noise);
//   * subsurface exits: a joint histogram of exit radius r (R log-spaced bins between kMinRadiusCm
//     and kMaxRadiusCm, within a bin log-uniform; plus [0, kMinRadiusCm) uniform in area and an
//     overflow [kMaxRadiusCm, largest radius seen) uniform) × offset azimuth |φ − φ_t| ∈ [0, π]
//     (A uniform bins; the sign is equally likely by the y → −y mirror symmetry);
//   * subsurface exit direction: P polar bins uniform in cosθ (θ from the outward normal, −z),
//     uniform within a bin; the exit azimuth is drawn uniformly (the renderer uses its own exit
//     lobe, skin_material.h, and hemispherical spectra do not need it);
//   * transmitted direction: P polar bins the same way (from +z); its lateral offset is not kept;
//   * sums and sums of squares for the hemispherical quantities, with standard errors
//     (BinStatistics: weight / N per outcome, exact in expectation).
// SkinPath::events of a sampled path counts the entry crossing only.
//
// Building: bins × rays walks (with ExitTableSettings::raysByUse, N_k walks in bin k instead of N:
// skin/exit_table_rays.h), ray i of bin k on Rng(seed, k, i), in fixed chunks run in parallel
// (TBB) and merged in chunk order: the table is the same at any thread count. With
// ExitTableSettings::tabulatedMelanosomes the build walks use WalkOptions::tabulatedMelanosomes.
// A bundle's build makes the same walks once for all its wavelengths (spectral paths with
// per-layer absorption), and the bundle (skin/spectral_bundle.h) must be able to share paths.
//
// File format (little-endian; skin/exit_table_file.cpp): "HYLXTAB1" | u64 format version | u64 key
// | u64 payload size | u64 FNV-1a 64 of the payload | payload (u64 and IEEE-754 doubles). The key
// hashes every input: all SkinOptics and WalkOptions fields (of every member, for a bundle's
// table, with the member's place), all settings and the format version. read() returns nullopt,
// never throws or crashes, for a missing, truncated, corrupt, stale or foreign file; write() is
// atomic (a temporary file renamed into place).
#pragma once
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "skin/core/random.h"
#include "skin/core/statistics.h"
#include "skin/core/vector3.h"
#include "skin/layer.h"
#include "skin/skin_optics.h"
#include "skin/skin_walk.h"
#include "skin/spectral_walk.h"

namespace hylios::skin {

/// Bump when the file layout, the walk's physics or what its paths draw changes (stale tables are
/// then rebuilt, so that a seed renders the same bits with a warm cache as with a cold one). 4:
/// the ziggurat's free paths and the doubled-angle azimuth (session 26), the spectral roulette
/// at 0.3 (session 27).
inline constexpr std::uint64_t kExitTableFormatVersion = 4;

struct ExitTableSettings {
  int cosineBins = 12;               ///< K, bins of the transmitted direction's cosine
  std::uint64_t raysPerBin = 40000;  ///< N, walks per bin
  std::uint64_t seed = 1;
  int radialBins = 96;               ///< R, log-spaced between kMinRadiusCm and kMaxRadiusCm
  int offsetAzimuthBins = 8;         ///< A, over |φ − φ_t| ∈ [0, π]
  int polarBins = 32;                ///< P, uniform in cosθ of the exit direction
  bool tabulatedMelanosomes = true;  ///< build with WalkOptions::tabulatedMelanosomes
  /// Walks per bin by how much rays from air can use the bin (skin/exit_table_rays.h): bin k gets
  /// the first N_k ≤ N of its N walks. false: every bin gets N.
  bool raysByUse = false;
};

/// Exact per-bin estimates (from the build's walks) with standard errors.
struct BinStatistics {
  double transmittedCosine = 0;  ///< μ_k
  std::uint64_t rays = 0;
  Estimate subsurface;  ///< P(subsurface exit | entered along μ_k)
  Estimate transmitted;
  Estimate absorbed;
  Estimate eventLimited;
  std::array<Estimate, kLayerCount> absorbedByLayer;
  Estimate meanExitRadiusCm;  ///< over subsurface exits
};

class ExitTable {
 public:
  static constexpr double kMinRadiusCm = 1e-5;
  static constexpr double kMaxRadiusCm = 30;

  /// Walks per bin for `walk` (the first walk of a bundle): N each, or by use (raysByUse).
  static std::vector<std::uint64_t> raysOfBins(const SkinWalk& walk,
                                               const ExitTableSettings& settings);
  /// The key of the table for these inputs (FNV-1a 64 of every field, skin/core/content_hash.h).
  static std::uint64_t key(const SkinOptics& optics, const WalkOptions& walk,
                           const ExitTableSettings& settings);
  /// The key of member `member` of a bundle's tables (buildBundle).
  static std::uint64_t bundleKey(const std::vector<const SkinWalk*>& bundle, std::size_t member,
                                 const ExitTableSettings& settings);
  /// Runs the walks. Throws std::invalid_argument for settings out of range (bins < 1 or above
  /// 4096, raysPerBin < 2 or above 2^32) and whatever SkinWalk's constructor throws.
  static ExitTable build(const SkinWalk& walk, const ExitTableSettings& settings);
  /// One table per walk of `bundle` (same order) from one set of spectral walks. The walks must
  /// share their WalkOptions and be able to share paths (SpectralWalk's constructor throws
  /// std::invalid_argument otherwise), as well as the settings' checks of build().
  static std::vector<ExitTable> buildBundle(const std::vector<const SkinWalk*>& bundle,
                                            const ExitTableSettings& settings);
  /// The table stored at `path` if it exists, is intact and was built for exactly these inputs;
  /// otherwise nullopt with the reason in *whyNot (when not null).
  static std::optional<ExitTable> read(const std::filesystem::path& path, const SkinWalk& walk,
                                       const ExitTableSettings& settings,
                                       std::string* whyNot = nullptr);
  /// The same for member `member` of a bundle's tables.
  static std::optional<ExitTable> readBundleMember(const std::filesystem::path& path,
                                                   const std::vector<const SkinWalk*>& bundle,
                                                   std::size_t member,
                                                   const ExitTableSettings& settings,
                                                   std::string* whyNot = nullptr);
  /// Writes the table atomically. Throws std::runtime_error when the file cannot be written.
  void write(const std::filesystem::path& path) const;

  /// One ray arriving from air along `incident` (z > 0), like SkinWalk::trace.
  SkinPath sample(const Vec3& incident, Rng& rng) const;
  /// The tabulated part alone, like SkinWalk::traceEntered: a ray that has just crossed into the
  /// skin along `transmitted` (unit, z > 0).
  SkinPath sampleEntered(const Vec3& transmitted, Rng& rng) const;

  std::uint64_t key() const { return key_; }
  /// How many wavelengths shared the build's walks (1: analog walks of this table's own).
  std::size_t bundleSize() const { return bundleSize_; }
  const ExitTableSettings& settings() const { return settings_; }
  const SkinWalk& walk() const { return walk_; }
  int bins() const { return settings_.cosineBins; }
  double binCosine(int bin) const { return (bin + 1.0) / settings_.cosineBins; }
  BinStatistics statistics(int bin) const;

  // The stored distributions (for tests): the fraction of a bin's subsurface exits per radial
  // cell (0: [0, kMinRadiusCm), 1..R: log bins, R+1: overflow), per offset-azimuth bin, per polar
  // bin.
  std::vector<double> radialDistribution(int bin) const;
  std::vector<double> offsetAzimuthDistribution(int bin) const;
  std::vector<double> exitPolarDistribution(int bin) const;
  /// Edges of radial cell c of bin `bin`: [radialCellLowerCm(c), radialCellUpperCm(bin, c)) (only
  /// the overflow cell's upper edge depends on the bin).
  double radialCellLowerCm(int cell) const;
  double radialCellUpperCm(int bin, int cell) const;

 private:
  struct Bin {
    std::uint64_t rays = 0;
    // Weights per outcome (analog walks: counts) and sums of the squared path weights.
    double subsurface = 0, transmitted = 0, eventLimited = 0;
    std::array<double, kLayerCount> absorbed{}, absorbedInMelanosome{};
    double subsurfaceSquares = 0, transmittedSquares = 0, eventLimitedSquares = 0;
    double absorbedSquares = 0;  ///< of a path's total absorbed weight
    std::array<double, kLayerCount> absorbedSquaresByLayer{};
    std::vector<double> offsetWeights;            ///< (R + 2) × A, radial-major
    std::vector<double> exitPolarWeights;         ///< P
    std::vector<double> transmittedPolarWeights;  ///< P
    double largestRadiusCm = 0;
    double radiusSumCm = 0, radiusSquaresSumCm2 = 0;  ///< weighted by the exit weight
    // Sampling tables (derived, not stored): cumulative weights.
    std::vector<double> outcomeCdf, offsetCdf, exitPolarCdf, transmittedPolarCdf;
    void merge(const Bin& other);
    void addSubsurface(double weight, double radiusCm, std::size_t cell, std::size_t exitPolar);
    void addTransmitted(double weight, std::size_t polar);
  };

  ExitTable(const SkinWalk& walk, const ExitTableSettings& settings, std::uint64_t key,
            std::size_t bundleSize);
  Bin& newBin();
  Bin emptyBin() const;  ///< zero weights, sized by the settings
  void prepareSampling();
  std::string serializePayload() const;
  bool parsePayload(const std::string& payload, std::string* whyNot);
  static std::optional<ExitTable> readWithKey(const std::filesystem::path& path, ExitTable table,
                                              std::string* whyNot);
  void tally(Bin& bin, const SkinPath& path) const;
  /// Where a spectral path lands in a bin's histograms: the same for every member of its bundle
  /// (the path's geometry is shared), so buildBundle computes it once per path.
  struct PathCells {
    double radiusCm = 0;
    std::size_t offset = 0;  ///< offsetCell of the exit offset (subsurface exits)
    std::size_t polar = 0;   ///< the exit (or shared transmitted) direction's polar bin
  };
  PathCells cellsOf(const SpectralPath& path) const;
  void tally(Bin& bin, const SpectralPath& path, std::size_t member, const PathCells& cells) const;
  /// A subsurface exit's cells: its radius, its offset cell (radial cell × the offset's azimuth
  /// from the entry's, folded to [0, π]) and the exit direction's polar bin.
  PathCells subsurfaceCells(double offsetXCm, double offsetYCm, const Vec3& exitDirection) const;
  int radialCell(double radiusCm) const;
  SkinPath sampleBin(const Bin& bin, const Vec3& transmitted, Rng& rng) const;
  /// The bin a ray entered along a direction of this cosine uses: the nearer centres' linear
  /// interpolation probabilities, drawn with u.
  int chooseBin(double transmittedCosine, double u) const;
  /// A radius in radial cell `radial` of bin `bin` by its law within the cell (v uniform).
  double radiusInCell(int bin, int radial, double v) const;
  friend class ExitTableBundle;  // samples a band's tables at once (skin/exit_table_bundle.h)

  SkinWalk walk_;
  ExitTableSettings settings_;
  std::uint64_t key_ = 0;
  std::size_t bundleSize_ = 1;
  std::vector<Bin> bins_;
};

}  // namespace hylios::skin
