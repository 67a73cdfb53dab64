// libFuzzer harness: parseSlabLayerSpec (`hylios slab --layer`) on arbitrary bytes. Bad input must
// throw a std::exception; an accepted layer must satisfy the constraints the header promises.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>

#include "app/slab_layer_spec.h"
#include "fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hylios;
  skin::SlabLayer layer;
  try {
    layer = parseSlabLayerSpec(fuzz::asText(data, size));
  } catch (const std::exception&) {
    return 0;
  }
  fuzz::require(std::isfinite(layer.refractiveIndex) && layer.refractiveIndex > 0,
                "n finite and > 0");
  fuzz::require(std::isfinite(layer.muA_perCm) && layer.muA_perCm >= 0, "mua finite and >= 0");
  fuzz::require(std::isfinite(layer.muS_perCm) && layer.muS_perCm >= 0, "mus finite and >= 0");
  fuzz::require(layer.anisotropyG > -1 && layer.anisotropyG < 1, "g in (-1, 1)");
  fuzz::require(!std::isnan(layer.thicknessCm) && layer.thicknessCm >= 0, "d >= 0 or inf");
  return 0;
}
