// libFuzzer harness: skin::SpectralExtensions::parse (assets/spectra/extensions.toml format) on
// arbitrary bytes. Bad input must throw a std::exception; accepted values must be finite and
// ordered as the loader promises.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <initializer_list>

#include "fuzz/fuzz_check.h"
#include "skin/spectral_extensions.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hylios;
  skin::SpectralExtensions x;
  try {
    x = skin::SpectralExtensions::parse(fuzz::asText(data, size), "fuzz_extensions.toml");
  } catch (const std::exception&) {
    return 0;
  }
  fuzz::require(x.domainMinNm > 0 && x.domainMinNm < x.domainMaxNm, "[domain] min < max");
  fuzz::require(x.hemoglobinFloorMinNm < x.hemoglobinFloorMaxNm, "hemoglobin floor range ordered");
  fuzz::require(x.bloodWaterVolumeFraction > 0 && x.bloodWaterVolumeFraction < 1,
                "blood water volume fraction in (0, 1)");
  for (double v : {x.eumelaninFitMinNm, x.pheomelaninFitMinNm, x.prahlHemoglobinMolarMass,
                   x.zijlstraHemoglobinMolarMass, x.bloodHemoglobinMgPerMl,
                   x.hemoglobinDecayLengthNm, x.cornOilFirstValidNm, x.bilirubinMolarMass,
                   x.bilirubinZeroFromNm, x.betaCaroteneMolarMass, x.betaCaroteneZeroFromNm})
    fuzz::require(std::isfinite(v) && v > 0, "every scalar is finite and > 0");
  for (const skin::MoleculeShare& m :
       {x.keratin.tyrosine, x.keratin.tryptophan, x.keratin.phenylalanine})
    fuzz::require(std::isfinite(m.share) && m.share > 0 && std::isfinite(m.molarMass) &&
                      m.molarMass > 0 && std::isfinite(m.zeroFromNm) && m.zeroFromNm > 0,
                  "keratin's molecules: finite, positive share, mass and end");
  fuzz::require(std::isfinite(x.keratin.densityMgPerMl) && x.keratin.densityMgPerMl > 0,
                "keratin density finite and > 0");
  fuzz::require(x.dna.gcFraction > 0 && x.dna.gcFraction < 1, "DNA GC fraction in (0, 1)");
  double shares = 0;
  for (const skin::MoleculeShare& m :
       {x.dna.adenine, x.dna.guanine, x.dna.cytosine, x.dna.thymine}) {
    fuzz::require(std::isfinite(m.zeroFromNm) && m.zeroFromNm > 0, "DNA bases' ends > 0");
    shares += m.share;
  }
  fuzz::require(std::fabs(shares - 1.0) < 1e-12, "DNA base shares sum to 1");
  return 0;
}
