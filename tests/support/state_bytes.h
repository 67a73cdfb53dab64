// The exact state of a tally as bytes (appendBytes, e.g. SkinTally, ControlledMeans), for tests
// that compare sums, counts and histograms bit for bit: equal bytes, equal state.
#pragma once
#include <string>

namespace hylios::test {

template <class Tally>
std::string stateBytes(const Tally& tally) {
  std::string bytes;
  tally.appendBytes(bytes);
  return bytes;
}

}  // namespace hylios::test
