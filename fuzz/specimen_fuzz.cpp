// libFuzzer harness: skin::parseSpecimen on arbitrary bytes. Bad input must throw a
// std::exception; a specimen it returns must pass validateSpecimen (finite, in range).
#include <cstddef>
#include <cstdint>
#include <exception>

#include "fuzz/fuzz_check.h"
#include "skin/specimen.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hylios;
  skin::Specimen specimen;
  try {
    specimen = skin::parseSpecimen(fuzz::asText(data, size), "fuzz.toml");
  } catch (const std::exception&) {
    return 0;  // rejected with a message: the expected outcome for most inputs
  }
  bool valid = true;
  try {
    skin::validateSpecimen(specimen);
  } catch (const std::exception&) {
    valid = false;
  }
  fuzz::require(valid, "a parsed specimen passes validateSpecimen");
  return 0;
}
