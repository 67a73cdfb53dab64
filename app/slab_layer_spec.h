// Parsing of `hylios slab --layer n=1.37,mua=1,mus=100,g=0.9,d=0.1`: one layer of the generic
// layered-slab problem as comma-separated key=value pairs (keys n, mua [cm^-1], mus [cm^-1], g,
// d [cm]; d may be "inf" for a semi-infinite last layer).
#pragma once
#include <string>

#include "skin/layered_slab.h"

namespace hylios {

/// Parses one --layer value. Throws std::invalid_argument naming the offending token: unknown,
/// repeated or missing key, a value that is not a number, NaN, negative, infinite (except d),
/// n <= 0, or g outside (-1, 1).
skin::SlabLayer parseSlabLayerSpec(const std::string& spec);

}  // namespace hylios
