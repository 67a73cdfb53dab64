// How often each member of a spectral bundle is the hero of a path (skin/spectral_walk.h).
//
// The walk draws a hero j with probability c_j and weights wavelength i by the balance heuristic
// p_i(path) / Σ_j c_j p_j(path), which is exact for any shares c_j > 0 (Σ c_j = 1). Uniform
// shares give a bundle's end members, whose laws have neighbours on one side only, the largest
// variance, and so does a member whose neighbours lie far from it in law: Algorithm 2's θo falls
// linearly in λ, so 5 nm steps are 0.008 apart in ln θo at 785 nm and 0.05 apart at 1300 nm.
// Shares by law spread the mixture evenly over the laws the bundle spans instead:
//
// | step                | value                                                                |
// |---------------------|----------------------------------------------------------------------|
// | law coordinates     | x = ln θo / reach.logAngle and y = ln τ / reach.logRayleighDepth      |
// |                     | (τ: the stack's Rayleigh optical depth at normal incidence); a law   |
// |                     | that is the same for every member (or 0) adds nothing                 |
// | gap g_j             | the distance from member j to j + 1 in (x, y) (members in λ order)   |
// | width w_j           | g_{j−1}/2 + g_j/2, an end member taking 1 (one reach) for its missing |
// |                     | side; at least kLeastWidth                                           |
// | share c_j           | w_j / Σ w; uniform when every gap is 0 (one law for all members)     |
//
// The reach is how far in a law's coordinate one path's MIS ratio still tells the laws apart
// (about 1/√(2n) in ln θo for n ≈ 35 melanosome deflections a path makes in the ramp; a few
// Rayleigh events per path in ln τ): docs/benchmarks.md, session 24, measured the defaults.
#pragma once
#include <cstddef>
#include <vector>

namespace hylios::skin {

struct HeroShareReach {
  double logAngle = 0.25;         ///< in ln θo (Algorithm 2)
  double logRayleighDepth = 0.6;  ///< in ln τ (Rayleigh, Eq. 4)
};

class HeroShares {
 public:
  /// The least width of a member, in reaches: members with the same law as a neighbour still
  /// lead some paths.
  static constexpr double kLeastWidth = 0.1;

  /// Uniform shares over `members` (at least 1).
  explicit HeroShares(std::size_t members = 1);
  /// Shares by law for members in increasing wavelength: θo (radians, ≥ 0) and τ (≥ 0) per
  /// member. Throws std::invalid_argument for arrays of different or zero size, a negative or
  /// non-finite value, or a reach that is not positive and finite.
  HeroShares(const std::vector<double>& meanAngleRad, const std::vector<double>& rayleighDepth,
             const HeroShareReach& reach = {});

  std::size_t size() const { return shares_.size(); }
  bool uniform() const { return uniform_; }
  const std::vector<double>& shares() const { return shares_; }
  /// log(n·c_j): the term hero j's proposal density takes in the mixture (0 when uniform).
  const std::vector<double>& logScaledShares() const { return logScaledShares_; }
  /// The hero for u uniform in [0, 1): with probability c_j (uniform: ⌊u·n⌋, as before shares).
  std::size_t draw(double u) const;

 private:
  bool uniform_ = true;
  std::vector<double> shares_, cumulative_, logScaledShares_;
};

}  // namespace hylios::skin
