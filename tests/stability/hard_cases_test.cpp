// Hard cases of the HyLIoS walk (docs/architecture.md, "Rules that hold everywhere"): each runs
// real specimens at the edges of the model and asserts finite outputs, exact energy balance (every
// ray ends in exactly one of reflected / transmitted / absorbed, so R + T + A = 1 per ray) and
// termination (no ray reaches the event bound; the mean number of events stays bounded).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "skin/core/constants.h"
#include "skin/core/random.h"
#include "skin/rough_surface.h"
#include "skin/sampling/cosine_sampling.h"
#include "skin/sampling/exponential_polar_sampling.h"
#include "skin/sampling/henyey_greenstein.h"
#include "skin/sampling/melanosome_orientation_sampling.h"
#include "skin/sampling/rayleigh_sampling.h"
#include "skin/sampling/surface_normal_sampling.h"
#include "skin/skin_optics.h"
#include "skin/skin_simulation.h"
#include "skin/specimen.h"
#include "skin/spectral_database.h"
#include "skin/spheroid_intersection.h"
#include "tests/support/test_spectra.h"

using hylios::kPi;

using namespace hylios::skin;

namespace {

const std::string kRoot = HYLIOS_SOURCE_DIR;

using hylios::test::spectra;

Specimen specimen(const std::string& name) {
  return loadSpecimen(name, kRoot + "/scenes/specimens");
}

/// Runs `rays` rays and checks the three invariants; returns the tally for further checks.
SkinTally expectStable(const Specimen& s, double wavelengthNm, double angleDeg,
                       std::uint64_t rays = 3000) {
  WalkRunOptions options;
  options.incidenceDeg = angleDeg;
  options.rays = rays;
  options.seed = 11;
  const SkinTally t = simulateSkin(computeSkinOptics(s, spectra(), wavelengthNm), options);
  const double balance = t.reflectance().mean + t.transmittance().mean + t.absorptance().mean;
  EXPECT_TRUE(std::isfinite(balance) && std::isfinite(t.reflectance().standardError));
  EXPECT_NEAR(balance, 1.0, 1e-12)
      << s.name << " at " << wavelengthNm << " nm, " << angleDeg << "°";
  EXPECT_EQ(t.eventLimited().mean, 0.0) << "rays stopped by the event bound";
  EXPECT_LT(t.meanEvents(), 1e4) << "mean events per ray";
  return t;
}

}  // namespace

TEST(HardCases, ExtremeAbsorptionAt250nmInS4) {
  const SkinTally t = expectStable(specimen("S4"), 250, 45);
  EXPECT_GT(t.absorptance().mean, 0.5);  // keratin, urocanic acid, DNA and melanin at 250 nm
}

TEST(HardCases, WaterBand1450nmInS4) { expectStable(specimen("S4"), 1450, 45); }
TEST(HardCases, WaterBand1940nmInS4) { expectStable(specimen("S4"), 1940, 45); }
TEST(HardCases, NormalIncidence) { expectStable(specimen("S1"), 550, 0); }

TEST(HardCases, GrazingIncidence89_9Degrees) {
  const SkinTally t = expectStable(specimen("S1"), 550, 89.9);
  EXPECT_GT(t.surfaceReflectance().mean, 0.5);  // Fresnel → 1 at grazing incidence
}

TEST(HardCases, FromInsideBeyondTheCriticalAngle) {
  // Leaving the stratum corneum (1.55) at 70° from the normal; the critical angle is 40.2°.
  Rng rng(3);
  const Vec3 d = normalize(Vec3{std::sin(70 * kPi / 180), 0, -std::cos(70 * kPi / 180)});
  int reflected = 0;
  for (int i = 0; i < 20000; ++i) {
    const InterfaceCrossing c = crossRoughSurface(d, 1.55, 1.0, 0.1, rng);
    ASSERT_TRUE(std::isfinite(c.direction.x) && std::isfinite(c.direction.z));
    ASSERT_NEAR(length(c.direction), 1.0, 1e-12);
    ASSERT_TRUE(c.transmitted ? c.direction.z < 0 : c.direction.z > 0);  // on the side it ended on
    reflected += c.transmitted ? 0 : 1;
  }
  EXPECT_GT(reflected, 15000);  // mostly total internal reflection; tilted facets let some out
}

TEST(HardCases, ZeroThicknessLayers) {
  Specimen s = specimen("S1");
  s.thicknessCm[index(Layer::StratumGranulosum)] = 0;
  s.thicknessCm[index(Layer::StratumSpinosum)] = 0;
  s.thicknessCm[index(Layer::PapillaryDermis)] = 0;
  expectStable(s, 550, 30);
}

TEST(HardCases, EmptyEpidermis) {
  Specimen s = specimen("S2");
  for (Layer l : {Layer::StratumCorneum, Layer::StratumGranulosum, Layer::StratumSpinosum,
                  Layer::StratumBasale})
    s.thicknessCm[index(l)] = 0;
  expectStable(s, 365, 30);
}

TEST(HardCases, MelanosomeContentZeroPercent) {
  Specimen s = specimen("S4");
  applyOverride(s, {"melanosome_percent", 0, "test"});
  const SkinTally t = expectStable(s, 365, 45);
  EXPECT_EQ(t.melanosomeAbsorptance().mean, 0.0);
}

TEST(HardCases, MelanosomeContentHundredPercent) {
  for (const char* name : {"S1", "S4"}) {  // complexes and dispersed melanosomes
    Specimen s = specimen(name);
    applyOverride(s, {"melanosome_percent", 100, "test"});
    expectStable(s, 365, 45, 1000);
    expectStable(s, 1650, 45, 1000);
  }
}

TEST(HardCases, ColloidalMelaninThirtyPercent) {
  Specimen s = specimen("S4");
  applyOverride(s, {"colloidal_melanin_percent", 30, "test"});
  expectStable(s, 365, 45);
}

TEST(HardCases, MeanScatteringAngleFallsToZeroAcrossTheNearInfrared) {
  const Specimen s = specimen("S4");
  for (double w = 780; w <= 1500; w += 60) expectStable(s, w, 45, 1000);
}

TEST(HardCases, SphericalMelanosomes) {
  Specimen s = specimen("S4");
  s.melanosomeMajorAxisUm = s.melanosomeMinorAxisUm;  // a = c
  expectStable(s, 450, 45);
}

TEST(HardCases, NeedleMelanosomes) {
  Specimen s = specimen("S4");
  s.melanosomeMajorAxisUm = 20 * s.melanosomeMinorAxisUm;  // c/a = 20
  expectStable(s, 450, 45);
}

TEST(HardCases, NearlySmoothSurface) {
  Specimen s = specimen("S1");
  s.surfaceFoldAspectRatio = 1e-6;
  expectStable(s, 550, 45);
}

TEST(HardCases, VeryRoughSurface) {
  Specimen s = specimen("S1");
  s.surfaceFoldAspectRatio = 2;
  expectStable(s, 550, 45);
}

TEST(HardCases, WaterReducedByHundredPercent) {
  Specimen s = specimen("S3");
  applyOverride(s, {"water_reduction_percent", 100, "test"});
  const SkinTally dry = expectStable(s, 1450, 8);
  const SkinTally wet = expectStable(specimen("S3"), 1450, 8);
  EXPECT_GT(dry.reflectance().mean, wet.reflectance().mean);  // no water band left
}

TEST(HardCases, ClearStackWithTotalInternalReflectionTerminates) {
  // Nothing absorbs; the surface index 1.55 traps most diffuse light by TIR, the hypodermis
  // reflects everything: every ray must still come out, in a bounded number of events.
  SkinOptics optics;
  optics.wavelengthNm = 600;
  optics.surfaceAspectRatio = 0.1;
  optics.melaninRefractiveIndex = 1.7;
  for (Layer l : kAllLayers) {
    optics.layers[index(l)].thicknessCm = 0.01;
    optics.layers[index(l)].refractiveIndex = l == Layer::StratumCorneum ? 1.55 : 1.4;
  }
  optics.layers[index(Layer::PapillaryDermis)].muRayleigh_perCm = 2500;
  WalkRunOptions options;
  options.rays = 5000;
  const SkinTally t = simulateSkin(optics, options);
  EXPECT_EQ(t.reflectance().mean, 1.0);
  EXPECT_EQ(t.eventLimited().mean, 0.0);
  EXPECT_LT(t.meanEvents(), 1000.0);
}

TEST(HardCases, SamplersAcceptTheExtremeUniformNumbers) {
  const ProlateSpheroid needle{0.01, 0.2}, sphere{0.1, 0.1};
  for (double u : {0.0, kOneMinusEpsilon}) {
    EXPECT_TRUE(std::isfinite(sampleRayleighPolar(u)));
    for (double theta0 : {0.0, 1e-12, 0.0873, 3.0})
      EXPECT_TRUE(std::isfinite(sampleExponentialPolar(theta0, u)));
    for (double s : {1e-6, 0.1, 2.0}) EXPECT_TRUE(std::isfinite(sampleSurfaceNormalPolar(s, u)));
    EXPECT_TRUE(std::isfinite(sampleCosinePolar(u)));
    for (double g : {0.0, 0.9, -0.9}) EXPECT_TRUE(std::isfinite(sampleHenyeyGreensteinCos(g, u)));
    for (double v : {0.0, kOneMinusEpsilon}) {
      const Vec3 h = sampleCosineHemisphere(u, v);
      EXPECT_TRUE(std::isfinite(h.x) && std::isfinite(h.z));
      for (const ProlateSpheroid& p : {needle, sphere}) {
        const Vec3 axis = sampleMelanosomeAxis(p, Vec3{0, 0, 1}, u, v);
        EXPECT_NEAR(length(axis), 1.0, 1e-12);
        const SpheroidSurfacePoint entry = sampleSilhouetteEntry(p, axis, Vec3{0, 0, 1}, u, v);
        EXPECT_TRUE(std::isfinite(entry.position.x) && std::isfinite(entry.outwardNormal.z));
      }
    }
  }
}
