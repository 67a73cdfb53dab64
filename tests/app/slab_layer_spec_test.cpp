// `--layer key=value,...` parsing for `hylios slab`: values, infinity, and an error per bad token.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "app/slab_layer_spec.h"

namespace hylios {
namespace {

std::string errorOf(const std::string& spec) {
  try {
    parseSlabLayerSpec(spec);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

TEST(SlabLayerSpecTest, ParsesAllKeysInAnyOrder) {
  const skin::SlabLayer layer = parseSlabLayerSpec("d=0.1,g=0.9,mus=100,mua=1,n=1.37");
  EXPECT_EQ(layer.refractiveIndex, 1.37);
  EXPECT_EQ(layer.muA_perCm, 1.0);
  EXPECT_EQ(layer.muS_perCm, 100.0);
  EXPECT_EQ(layer.anisotropyG, 0.9);
  EXPECT_EQ(layer.thicknessCm, 0.1);
  EXPECT_TRUE(std::isinf(parseSlabLayerSpec("n=1.5,mua=10,mus=90,g=0,d=inf").thicknessCm));
  EXPECT_TRUE(std::isinf(parseSlabLayerSpec("n=1.5,mua=10,mus=90,g=0,d=infinity").thicknessCm));
  EXPECT_EQ(parseSlabLayerSpec("n=1,mua=0,mus=0,g=-0.5,d=1e-3").anisotropyG, -0.5);
}

TEST(SlabLayerSpecTest, ErrorsNameTheOffendingToken) {
  EXPECT_NE(errorOf("n=1.37,mua=1,mus=100,g=0.9").find("missing key 'd'"), std::string::npos);
  EXPECT_NE(errorOf("n=1.37,mua=1,mus=100,g=0.9,d=1,k=2").find("unknown key 'k'"),
            std::string::npos);
  EXPECT_NE(errorOf("n=1.37,mua=-1,mus=100,g=0.9,d=1").find("'mua' must be >= 0, got -1"),
            std::string::npos);
  EXPECT_NE(errorOf("n=1.37,mua=1,mus=nan,g=0.9,d=1").find("'mus=nan' is NaN"), std::string::npos);
  EXPECT_NE(errorOf("n=1.37,mua=1,mus=1x,g=0.9,d=1").find("'mus=1x' is not a number"),
            std::string::npos);
  EXPECT_NE(errorOf("n=1.37,mua=1,mus=1,g=0.9,d=").find("'d' has no value"), std::string::npos);
  EXPECT_NE(errorOf("n=1.37,mua=inf,mus=1,g=0.9,d=1").find("infinite"), std::string::npos);
  EXPECT_NE(errorOf("n=1.37,mua=1,mus=1,g=0.9,d=-inf").find("infinite"), std::string::npos);
  EXPECT_NE(errorOf("n=1.37,n=1.4,mua=1,mus=1,g=0.9,d=1").find("'n' given twice"),
            std::string::npos);
  EXPECT_NE(errorOf("n=0,mua=1,mus=1,g=0,d=1").find("'n' must be > 0"), std::string::npos);
  EXPECT_NE(errorOf("n=1,mua=1,mus=1,g=1,d=1").find("'g' must be in (-1, 1)"), std::string::npos);
  EXPECT_NE(errorOf("n=1,mua=1,mus=1,g=0,d=1,oops").find("token 'oops'"), std::string::npos);
  EXPECT_NE(errorOf("n=1,mua=1,mus=1,g=0,d=1e999").find("not a number"), std::string::npos);
}

}  // namespace
}  // namespace hylios
