#include "skin/layered_slab_lanes.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include "skin/core/float_lanes.h"
#include "skin/core/lane_random.h"
#include "skin/sampling/henyey_greenstein_lanes.h"

// GCC on x86-64: an AVX2 clone of the walk besides the baseline (SSE2), chosen at load time.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__ELF__)
#define HYLIOS_LANE_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define HYLIOS_LANE_CLONES
#endif

namespace hylios::skin {
namespace {

using namespace lanes;

// GCC notes that a 32-byte vector argument or return "changes the ABI" without AVX (silenced for
// this file in skin/CMakeLists.txt). Every function here that takes or returns a vector is
// force-inlined, so none crosses a call. Keep it so: a helper that is not inlined (a lambda, say)
// is compiled for the baseline and would be called from the AVX2 clone with the other convention,
// and the lanes would read garbage.

// The scalar walk's roulette (kSlabRouletteThreshold, kSlabRouletteSurvival). On the uniform grid
// k·2⁻²⁴ the test u < P has probability exactly P for P = the survival rounded up to the grid
// (1677722·2⁻²⁴ for 0.1), and the survivor carries 1/P.
constexpr float kRouletteThreshold = static_cast<float>(kSlabRouletteThreshold);
constexpr double kSurvivalOnGrid = kSlabRouletteSurvival * 0x1.0p24;
constexpr float kSurvivalProbability =
    static_cast<float>(static_cast<std::uint32_t>(kSurvivalOnGrid) +
                       (static_cast<std::uint32_t>(kSurvivalOnGrid) < kSurvivalOnGrid ? 1u : 0u)) *
    0x1.0p-24f;
static_assert(kSurvivalProbability == 1677722.0f * 0x1.0p-24f, "0.1 rounded up to the 2^-24 grid");
constexpr float kInverseSurvivalProbability = 1.0f / kSurvivalProbability;

// The constants of each lane's layer, refreshed only when a packet changes layer.
struct LayerLanes {
  Floats zTop, zBottom, muT, inverseMuT, absorptionProbability;
  HenyeyGreensteinLanes hg;
};

// The packets in the lanes. absorbed[8k + l] holds lane l's weight absorbed in layer k before
// its present stay; absorbedHere the stay's own.
struct Lanes {
  Floats z, ux, uy, uz, weight, opticalDepth, absorbedHere;
  Ints layer, needsDepth, scattered, active, events;
  LayerLanes constants;
  LaneRng rng;
  std::uint64_t packet[kLanes];
  std::vector<float> absorbed;
};

constexpr int kGroups = 2;

// How each lane's step ended: absorbed to its end by roulette, or left through the top or bottom.
struct StepEnds {
  Ints ended, leftTop, leftBottom, eventLimited, scatteredBefore, changedLayer;
};

// table[index] per lane; `small`: the table has at most eight entries (padded to eight).
template <typename Table>
HYLIOS_LANES_INLINE auto lookUp(const Table& table, Ints index, bool small) {
  if constexpr (std::is_same_v<typename Table::value_type, float>)
    return small ? permute(table.data(), index) : gather(table.data(), index);
  else
    return small ? permuteInt(table.data(), index) : gatherInt(table.data(), index);
}

// Lanes in `mask` take the constants of their (new) layer.
HYLIOS_LANES_INLINE void refreshLayer(const SlabLaneWalker::Tables& t, Ints mask, Lanes& p) {
  LayerLanes& c = p.constants;
  const Ints k = p.layer;
  const bool small = t.muT.size() <= kLanes;
  c.zTop = select(mask, lookUp(t.zTop, k, small), c.zTop);
  c.zBottom = select(mask, lookUp(t.zBottom, k, small), c.zBottom);
  c.muT = select(mask, lookUp(t.muT, k, small), c.muT);
  c.inverseMuT = select(mask, lookUp(t.inverseMuT, k, small), c.inverseMuT);
  c.absorptionProbability =
      select(mask, lookUp(t.absorptionProbability, k, small), c.absorptionProbability);
  HenyeyGreensteinLanes& hg = c.hg;
  hg.g = select(mask, lookUp(t.g, k, small), hg.g);
  hg.oneMinusG = select(mask, lookUp(t.oneMinusG, k, small), hg.oneMinusG);
  hg.twoTimesG = select(mask, lookUp(t.twoTimesG, k, small), hg.twoTimesG);
  hg.twoOneMinusGSquared =
      select(mask, lookUp(t.twoOneMinusGSquared, k, small), hg.twoOneMinusGSquared);
  hg.twoOnePlusGSquared =
      select(mask, lookUp(t.twoOnePlusGSquared, k, small), hg.twoOnePlusGSquared);
}

// Lanes in `mask` add their stay's absorption to the layer they are in.
HYLIOS_LANES_INLINE void bookStay(Ints mask, Lanes& p) {
  for (std::size_t k = 0; k * kLanes < p.absorbed.size(); ++k) {
    float* absorbed = p.absorbed.data() + k * kLanes;
    const Ints here = mask & (p.layer == static_cast<std::int32_t>(k));
    store(absorbed, load(absorbed) + select(here, p.absorbedHere, Floats{}));
  }
  p.absorbedHere = select(mask, Floats{}, p.absorbedHere);
}

// A meeting with the boundary ahead (FresnelPair::reflectance per lane, one coin): whether each
// lane reflects, and the refraction cosine of those that cross.
struct BoundaryMeeting {
  Ints reflects;
  Floats eta, cosTransmitted;
};

HYLIOS_LANES_INLINE BoundaryMeeting meetBoundary(const SlabLaneWalker::Tables& t, Ints down,
                                                 Floats uz, Floats coin, const Lanes& p) {
  const Ints boundary = p.layer * 2 + (down & 1);
  const bool small = t.eta.size() <= kLanes;
  const Floats relative = lookUp(t.relativeIndex, boundary, small);
  const Floats c = min(abs(uz), splat(1.0f));
  const Floats cosTSquared =
      lookUp(t.oneMinusEtaSquared, boundary, small) + lookUp(t.etaSquared, boundary, small) * c * c;
  const Floats cosT = sqrt(max(cosTSquared, Floats{}));
  const Floats sN = c - relative * cosT, sD = c + relative * cosT;
  const Floats pN = cosT - relative * c, pD = cosT + relative * c;
  const Floats sN2 = sN * sN, sD2 = sD * sD, pN2 = pN * pN, pD2 = pD * pD;
  const Floats fresnel = 0.5f * (sN2 * pD2 + pN2 * sD2) / (sD2 * pD2);
  const Floats reflectance = select(lookUp(t.matched, boundary, small), Floats{},
                                    select(cosTSquared <= 0.0f, splat(1.0f), fresnel));
  return {(reflectance >= 1.0f) | (coin < reflectance), lookUp(t.eta, boundary, small), cosT};
}

// One event for every lane: a scattering inside the layer (deposit, roulette, Henyey–Greenstein)
// or a meeting with the layer's boundary (Fresnel reflection or refraction into the next layer or
// out of the stack), as SlabWalker::trace does for one packet.
HYLIOS_LANES_INLINE StepEnds step(const SlabLaneWalker::Tables& t, std::int32_t lastLayer,
                                  std::int32_t eventLimit, Lanes& p) {
  const LayerLanes& c = p.constants;
  // As the scalar walk: a packet at its (event limit + 1)-th event stops with its weight.
  p.events += 1;
  const Ints limited = p.active & (p.events > eventLimit);
  const Ints going = p.active & ~limited;
  const Floats u0 = p.rng.uniform(), u1 = p.rng.uniform(), u2 = p.rng.uniform();
  const Floats u3 = p.rng.uniform();  // the Fresnel coin, or the roulette's (never both)
  const Floats opticalDepth = select(p.needsDepth, -laneLog(1.0f - u0), p.opticalDepth);
  const Ints down = p.uz > 0.0f, up = p.uz < 0.0f;
  const Floats boundaryZ = select(down, c.zBottom, c.zTop);
  const Floats distance =
      select(down | up, (boundaryZ - p.z) / p.uz, splat(std::numeric_limits<float>::infinity()));
  const Floats depthToBoundary = c.muT * distance;
  const Ints interacts = opticalDepth < depthToBoundary;

  // Scattering: implicit capture, roulette, a Henyey–Greenstein turn.
  const Floats zInside = p.z + p.uz * (opticalDepth * c.inverseMuT);
  const Floats deposit = select(interacts & ~limited, p.weight * c.absorptionProbability, Floats{});
  p.absorbedHere += deposit;
  const Floats kept = p.weight - deposit;
  const Ints low = kept < kRouletteThreshold;
  const Ints survives = (u3 < kSurvivalProbability) & (kept > 0.0f);
  const Floats keptAfterRoulette =
      select(low, select(survives, kept * kInverseSurvivalProbability, Floats{}), kept);
  Floats cosTheta, sinTheta;
  sampleHenyeyGreensteinLanes(c.hg, u1, cosTheta, sinTheta);
  Floats sx = p.ux, sy = p.uy, sz = p.uz;
  turnLanes(sx, sy, sz, cosTheta, sinTheta, u2);

  StepEnds ends{};
  ends.scatteredBefore = p.scattered;
  ends.eventLimited = limited;
  ends.ended = (going & interacts & low & ~survives) | limited;
  p.z = select(interacts, zInside, boundaryZ);
  p.opticalDepth = select(interacts, Floats{}, opticalDepth - depthToBoundary);
  p.weight = select(interacts, keptAfterRoulette, p.weight);
  p.needsDepth = interacts;
  p.scattered = p.scattered | interacts;
  const BoundaryMeeting meeting = meetBoundary(t, down, p.uz, u3, p);
  const Ints crosses = ~interacts & ~meeting.reflects & going;
  ends.leftTop = crosses & ~down & (p.layer == 0);
  ends.leftBottom = crosses & down & (p.layer == lastLayer);
  ends.ended |= ends.leftTop | ends.leftBottom;
  ends.changedLayer = crosses & ~ends.leftTop & ~ends.leftBottom;
  p.ux = select(interacts, sx, select(meeting.reflects, p.ux, p.ux * meeting.eta));
  p.uy = select(interacts, sy, select(meeting.reflects, p.uy, p.uy * meeting.eta));
  p.uz = select(interacts, sz,
                select(meeting.reflects, -p.uz, copySign(meeting.cosTransmitted, p.uz)));
  if (any(ends.changedLayer)) {
    bookStay(ends.changedLayer, p);
    p.layer =
        selectInt(ends.changedLayer, p.layer + selectInt(down, splatInt(1), splatInt(-1)), p.layer);
    refreshLayer(t, ends.changedLayer, p);
  }
  return ends;
}

// The lanes in `mask` take the next packets of the range; a lane that finds none left idles
// (inactive, weight 0, in layer 1).
HYLIOS_LANES_INLINE void launch(const SlabLaneWalker& lanes, std::uint64_t seed, std::uint64_t last,
                                const Ints& mask, std::uint64_t& next, Lanes& p) {
  const SlabWalker& walker = lanes.walker();
  const SlabLaneWalker::Launch& start = lanes.launchState();
  p.z = select(mask, Floats{}, p.z);
  p.ux = select(mask, splat(start.ux), p.ux);
  p.uy = select(mask, Floats{}, p.uy);
  p.uz = select(mask, splat(start.uz), p.uz);
  p.weight = select(mask, splat(start.weight), p.weight);
  p.opticalDepth = select(mask, Floats{}, p.opticalDepth);
  p.absorbedHere = select(mask, Floats{}, p.absorbedHere);
  p.layer = selectInt(mask, Ints{}, p.layer);
  p.events = selectInt(mask, Ints{}, p.events);
  p.needsDepth |= mask;
  p.scattered &= ~mask;
  p.active |= mask;
  for (std::size_t k = 0; k * kLanes < p.absorbed.size(); ++k) {
    float* absorbed = p.absorbed.data() + k * kLanes;
    store(absorbed, select(mask, Floats{}, load(absorbed)));
  }
  for (int l = 0; l < kLanes; ++l) {
    if (!mask[l]) continue;
    if (next == last) {
      p.active[l] = 0;
      p.weight[l] = 0.0f;
      continue;
    }
    Rng rng(seed, 0, next);
    if (walker.diffuseIncidence()) {
      const Vec3 u = walker.launchDirection(rng);
      p.ux[l] = static_cast<float>(u.x);
      p.uz[l] = static_cast<float>(u.z);
    }
    p.rng.seedLane(l, rng);
    p.packet[l] = next++;
  }
  refreshLayer(lanes.tables(), mask, p);
}

// Writes the rows of the packets that ended and gives their lanes the next packets.
HYLIOS_LANES_INLINE void finishPackets(const SlabLaneWalker& lanes, Lanes& p, const StepEnds& ends,
                                       const Floats& weight, std::uint64_t seed,
                                       std::uint64_t first, std::uint64_t last, std::uint64_t& next,
                                       double* scores) {
  const std::size_t stride = lanes.scoresPerPacket();
  const std::size_t layers = stride - SlabLaneWalker::kFirstLayerAbsorptance;
  bookStay(ends.ended, p);
  for (int l = 0; l < kLanes; ++l) {
    if (!ends.ended[l]) continue;
    double* row = scores + (p.packet[l] - first) * stride;
    row[SlabLaneWalker::kDiffuseReflectance] = ends.leftTop[l] ? weight[l] : 0.0;
    row[SlabLaneWalker::kTransmittance] = ends.leftBottom[l] ? weight[l] : 0.0;
    row[SlabLaneWalker::kUnscatteredTransmittance] =
        ends.leftBottom[l] && !ends.scatteredBefore[l] ? weight[l] : 0.0;
    row[SlabLaneWalker::kEventLimited] = ends.eventLimited[l] ? weight[l] : 0.0;
    for (std::size_t k = 0; k < layers; ++k)
      row[SlabLaneWalker::kFirstLayerAbsorptance + k] = p.absorbed[k * kLanes + l];
  }
  launch(lanes, seed, last, ends.ended, next, p);
}

}  // namespace

bool SlabLaneWalker::represents(const SlabWalker& walker) {
  constexpr double kLargest = 1e30, kSmallest = 1e-30, kSmallestRelativeThickness = 0x1.0p-10;
  if (walker.eventLimit() > 0x7fffffffu) return false;  // the lanes count events in int32
  const std::vector<SlabWalker::LayerData>& layers = walker.layers();
  for (std::size_t k = 0; k < layers.size(); ++k) {
    const SlabWalker::LayerData& layer = layers[k];
    const double thickness = layer.zBottomCm - layer.zTopCm;
    const bool semiInfinite = k + 1 == layers.size() && std::isinf(layer.zBottomCm);
    const double muT = layer.muT_perCm;
    if (!(muT == 0 || (muT >= kSmallest && muT <= kLargest))) return false;
    if (semiInfinite || thickness == 0) continue;
    if (!(layer.zBottomCm <= kLargest && thickness >= kSmallest &&
          thickness >= kSmallestRelativeThickness * layer.zBottomCm))
      return false;
  }
  return true;
}

SlabLaneWalker::SlabLaneWalker(const SlabWalker& walker)
    : walker_(walker), layerCount_(walker.layerCount()) {
  if (walker.scheme() != AbsorptionScheme::WeightWithRoulette)
    throw std::invalid_argument("SlabLaneWalker: the lane walk is the weighted scheme only");
  if (!represents(walker))
    throw std::invalid_argument(
        "SlabLaneWalker: the stack needs double precision (a coefficient or depth above 1e30, or "
        "a layer thinner than 2^-10 of its depth) or the event limit is 2^31 or more");
  const auto f = [](double x) { return static_cast<float>(x); };
  Rng beamRng(0);  // a beam's direction draws nothing (diffuse light: drawn per packet)
  const Vec3 beam = walker.launchDirection(beamRng);
  launch_ = {f(beam.x), f(beam.z), f(walker.launchWeight())};
  for (const SlabWalker::LayerData& layer : walker.layers()) {
    tables_.zTop.push_back(f(layer.zTopCm));
    tables_.zBottom.push_back(f(layer.zBottomCm));
    tables_.muT.push_back(f(layer.muT_perCm));
    tables_.inverseMuT.push_back(layer.muT_perCm > 0 ? f(1.0 / layer.muT_perCm) : 0.0f);
    tables_.absorptionProbability.push_back(f(layer.absorptionProbability));
    const double g = layer.g;
    tables_.g.push_back(f(g));
    tables_.oneMinusG.push_back(f(1.0 - g));
    tables_.twoTimesG.push_back(f(2.0 * g));
    tables_.twoOneMinusGSquared.push_back(f(2.0 * (1.0 - g) * (1.0 - g)));
    tables_.twoOnePlusGSquared.push_back(f(2.0 * (1.0 + g) * (1.0 + g)));
    for (const double nBeyond : {layer.nAbove, layer.nBelow}) {  // index 2k: up, 2k + 1: down
      const double eta = layer.n / nBeyond;
      tables_.eta.push_back(f(eta));
      tables_.etaSquared.push_back(f(eta * eta));
      tables_.oneMinusEtaSquared.push_back(f((1.0 - eta) * (1.0 + eta)));
      tables_.relativeIndex.push_back(f(nBeyond / layer.n));
      tables_.matched.push_back(layer.n == nBeyond ? -1 : 0);
    }
  }
  if (layerCount_ <= static_cast<std::size_t>(kLanes)) {  // pad for the permutes
    for (std::vector<float>* table :
         {&tables_.zTop, &tables_.zBottom, &tables_.muT, &tables_.inverseMuT,
          &tables_.absorptionProbability, &tables_.g, &tables_.oneMinusG, &tables_.twoTimesG,
          &tables_.twoOneMinusGSquared, &tables_.twoOnePlusGSquared})
      table->resize(kLanes, 0.0f);
  }
  if (tables_.eta.size() <= static_cast<std::size_t>(kLanes)) {
    for (std::vector<float>* table :
         {&tables_.eta, &tables_.etaSquared, &tables_.oneMinusEtaSquared, &tables_.relativeIndex})
      table->resize(kLanes, 1.0f);
    tables_.matched.resize(kLanes, -1);
  }
}

HYLIOS_LANE_CLONES
void SlabLaneWalker::trace(std::uint64_t seed, std::uint64_t first, std::uint64_t last,
                           double* scores) const {
  const auto lastLayer = static_cast<std::int32_t>(layerCount_ - 1);
  // At most 2^31 - 1: represents() checks it.
  const auto eventLimit = static_cast<std::int32_t>(walker_.eventLimit());
  // Two groups of lanes stepped in turn: each step is one long chain of dependent operations, and
  // the other group's step fills the time its latencies leave.
  Lanes groups[kGroups] = {};  // zeros: lanes that never get a packet stay in layer 1 at weight 0
  std::uint64_t next = first;
  const Ints everyLane = Ints{} - 1;
  for (Lanes& p : groups) {
    p.absorbed.assign(layerCount_ * kLanes, 0.0f);
    launch(*this, seed, last, everyLane, next, p);
  }
  for (;;) {
    Ints active = Ints{};
    for (const Lanes& p : groups) active |= p.active;
    if (!any(active)) return;
    Floats weights[kGroups];  // the weights as the packets leave
    StepEnds ends[kGroups];
    for (int g = 0; g < kGroups; ++g) {
      weights[g] = groups[g].weight;
      ends[g] = step(tables_, lastLayer, eventLimit, groups[g]);
    }
    for (int g = 0; g < kGroups; ++g)
      if (any(ends[g].ended))
        finishPackets(*this, groups[g], ends[g], weights[g], seed, first, last, next, scores);
  }
}

}  // namespace hylios::skin
