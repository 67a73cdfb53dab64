#include <gtest/gtest.h>

#include <stdexcept>

#include "app/wavelength_list.h"

using hylios::parseWavelengthList;

TEST(WavelengthList, RangeIncludesStopOnTheGrid) {
  const auto w = parseWavelengthList("250:2500:5");
  ASSERT_EQ(w.size(), 451u);  // (2500 - 250) / 5 + 1
  EXPECT_DOUBLE_EQ(w.front(), 250.0);
  EXPECT_DOUBLE_EQ(w.back(), 2500.0);
}

TEST(WavelengthList, RangeStopsBeforeAnOffGridStop) {
  const auto w = parseWavelengthList("400:410:3");
  ASSERT_EQ(w.size(), 4u);
  EXPECT_DOUBLE_EQ(w.back(), 409.0);
}

TEST(WavelengthList, CommaList) {
  const auto w = parseWavelengthList("365,550.5,1100");
  ASSERT_EQ(w.size(), 3u);
  EXPECT_DOUBLE_EQ(w[1], 550.5);
}

namespace {
void expectError(const std::string& text, const std::string& fragment) {
  try {
    parseWavelengthList(text);
    FAIL() << "no error for '" << text << "'";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}
}  // namespace

TEST(WavelengthList, ErrorsNameTheProblem) {
  expectError("250:2500:0", "'0' is not a positive wavelength");
  expectError("250:abc:5", "'abc' is not a number");
  expectError("250:2500", "a range is start:stop:step");
  expectError("500:400:5", "stop is below start");
  expectError("365,,550", "empty value");
  expectError("nan", "not finite");
  expectError("", "no wavelengths given");
  // Found by fuzz/wavelength_list_fuzz: 1000 + i·1e-13 repeats values (doubles near 1000 are
  // 1.1e-13 apart), so the range would list the same wavelength twice.
  expectError("1000:1000.000000000001:1e-13", "step is too small to separate wavelengths");
}

TEST(WavelengthList, RefusesWavelengthsOutsideTheModelNamingTheOption) {
  expectError("2600", "--wavelengths '2600': 2600 nm is outside the model's range 250–2500 nm");
  expectError("365,249.5,550", "249.5 nm is outside the model's range");
  expectError("250:2600:5", "--wavelengths '250:2600:5': 2505 nm is outside");
  expectError("100:300:50", "100 nm is outside");
  EXPECT_EQ(parseWavelengthList("250,2500").size(), 2u);  // the domain's ends are inside
}
