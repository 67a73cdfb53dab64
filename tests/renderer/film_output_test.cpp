// Film output: spectral channel names, the EXR (names, attributes, values, read back with
// OpenImageIO), the PNG previews (sizes, colours), atomicity on a non-finite film, contact sheets.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>

#include "renderer/image/colour_tables.h"
#include "renderer/image/film_output.h"
#include "renderer/image/preview_image.h"
#include "tests/support/test_folder.h"

namespace {

namespace fs = std::filesystem;
using hylios::BandDesc;
using hylios::Film;
using hylios::FilmDesc;

/// A fresh, empty folder per test, removed afterwards.
class FilmOutputTest : public ::testing::Test {
 protected:
  void SetUp() override { folder_ = hylios::test::freshTestFolder("hylios_film_output_"); }
  void TearDown() override { fs::remove_all(folder_); }
  std::set<fs::path> folderContents() const {
    std::set<fs::path> files;
    for (const auto& entry : fs::directory_iterator(folder_)) files.insert(entry.path());
    return files;
  }
  fs::path folder_;
};

BandDesc singleBand(const std::string& name, double nm, double previewMin, double previewMax) {
  BandDesc band;
  band.name = name;
  band.minNm = band.maxNm = nm;
  band.previewMin = previewMin;
  band.previewMax = previewMax;
  return band;
}

/// 4×3 film: uv365 (preview 0–2), visible 380–780 nm every 10 nm, ir1100 (preview 0–1).
FilmDesc testDesc() {
  FilmDesc desc;
  desc.width = 4;
  desc.height = 3;
  desc.exposure = 0.5;
  BandDesc visible;
  visible.name = "visible";
  visible.minNm = 380;
  visible.maxNm = 780;
  visible.stepNm = 10;
  desc.bands = {singleBand("uv365", 365, 0.0, 2.0), visible, singleBand("ir1100", 1100, 0.0, 1.0)};
  return desc;
}

/// Pixel (x, y): uv = 0.5·x, ir = 0.25·y, visible = D65(λ)/100·grey(x) with grey = (x + 1)/4:
/// a grey diffuser of albedo grey(x) under a uniform "d65" environment of scale 1.
double uvValue(int x) { return 0.5 * x; }
double irValue(int y) { return 0.25 * y; }
double grey(int x) { return (x + 1) / 4.0; }

Film filledFilm() {
  Film film(testDesc());
  for (int y = 0; y < film.height(); ++y) {
    for (int x = 0; x < film.width(); ++x) {
      for (std::size_t c = 0; c < film.channels().size(); ++c) {
        const double nm = film.channels()[c].wavelengthNm;
        const double v = film.channels()[c].band == 0   ? uvValue(x)
                         : film.channels()[c].band == 2 ? irValue(y)
                                                        : hylios::d65(nm) / 100.0 * grey(x);
        film.addSample(x, y, c, v);
      }
    }
  }
  film.setSamplesPerPixelDone(7);
  return film;
}

struct ReadImage {
  OIIO::ImageSpec spec;
  std::vector<float> pixels;
  float at(int x, int y, int c) const {
    return pixels[(static_cast<std::size_t>(y) * spec.width + x) * spec.nchannels + c];
  }
};

ReadImage readImage(const fs::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) throw std::runtime_error("cannot open " + path.string() + ": " + OIIO::geterror());
  ReadImage image;
  image.spec = in->spec();
  image.pixels.resize(static_cast<std::size_t>(image.spec.width) * image.spec.height *
                      image.spec.nchannels);
  if (!in->read_image(0, 0, 0, image.spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
    throw std::runtime_error("cannot read " + path.string());
  return image;
}

TEST(SpectralChannelName, FormatAndParse) {
  EXPECT_EQ(hylios::spectralChannelName(365), "S0.365,000000nm");
  EXPECT_EQ(hylios::spectralChannelName(1100), "S0.1100,000000nm");
  EXPECT_EQ(hylios::spectralChannelName(532.25), "S0.532,250000nm");
  EXPECT_DOUBLE_EQ(*hylios::parseSpectralChannelName("S0.532,250000nm"), 532.25);
  EXPECT_DOUBLE_EQ(*hylios::parseSpectralChannelName("S0.1100,000000nm"), 1100.0);
  EXPECT_FALSE(hylios::parseSpectralChannelName("R").has_value());
  EXPECT_FALSE(hylios::parseSpectralChannelName("S0.abcnm").has_value());
  EXPECT_FALSE(hylios::parseSpectralChannelName("S0.365.5nm").has_value());
  EXPECT_FALSE(hylios::parseSpectralChannelName("T.365,000000nm").has_value());
  EXPECT_THROW(hylios::spectralChannelName(0), std::invalid_argument);
  EXPECT_THROW(hylios::spectralChannelName(std::nan("")), std::invalid_argument);
}

TEST(ColourBand, NormalisationMakesD65White) {
  const BandDesc visible = testDesc().bands[1];
  ASSERT_TRUE(hylios::isColourBand(visible));
  EXPECT_FALSE(hylios::isColourBand(testDesc().bands[0]));
  double y = 0;
  for (double nm = 380; nm <= 780; nm += 10)
    y += hylios::d65(nm) / 100 * hylios::cie1931(nm)[1] * 10;
  EXPECT_NEAR(hylios::colourBandNormalisation(visible), 1.0 / y, 1e-15);
}

TEST_F(FilmOutputTest, ExrHoldsChannelsAttributesAndValues) {
  const Film film = filledFilm();
  const fs::path exr = folder_ / "shot.exr";
  const auto written = hylios::writeFilmOutputs(film, exr);
  ASSERT_FALSE(written.empty());
  EXPECT_EQ(written.front(), exr);

  const ReadImage image = readImage(exr);
  EXPECT_EQ(image.spec.width, 4);
  EXPECT_EQ(image.spec.height, 3);
  // Channel order in the file is OpenEXR's (alphabetical: "S0.1100…" before "S0.365…"), so map
  // names to wavelengths rather than relying on positions.
  std::map<double, int> spectralIndex;
  std::map<std::string, int> rgbIndex;
  for (int c = 0; c < image.spec.nchannels; ++c) {
    const std::string& name = image.spec.channelnames[c];
    if (const auto nm = hylios::parseSpectralChannelName(name)) {
      spectralIndex[*nm] = c;
    } else {
      rgbIndex[name] = c;
    }
  }
  ASSERT_EQ(spectralIndex.size(), film.channels().size());
  for (const auto& channel : film.channels())
    EXPECT_EQ(spectralIndex.count(channel.wavelengthNm), 1u);
  ASSERT_EQ(rgbIndex.size(), 3u);
  ASSERT_EQ(rgbIndex.count("R") + rgbIndex.count("G") + rgbIndex.count("B"), 3u);

  EXPECT_EQ(image.spec.get_string_attribute("spectralLayoutVersion"), "1.0");
  EXPECT_EQ(image.spec.get_string_attribute("emissiveUnits"), "W.m^-2.sr^-1");
  EXPECT_EQ(image.spec.get_int_attribute("hylios:spp", -1), 7);

  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 4; ++x) {
      EXPECT_FLOAT_EQ(image.at(x, y, spectralIndex.at(365)), static_cast<float>(uvValue(x)));
      EXPECT_FLOAT_EQ(image.at(x, y, spectralIndex.at(1100)), static_cast<float>(irValue(y)));
      EXPECT_FLOAT_EQ(image.at(x, y, spectralIndex.at(560)), static_cast<float>(grey(x)));
      // D65/100 times grey(x) is a neutral grey of luminance grey(x); RGB carries exposure 0.5.
      for (const char* name : {"R", "G", "B"})
        EXPECT_NEAR(image.at(x, y, rgbIndex.at(name)), 0.5 * grey(x), 1e-2 * 0.5 * grey(x)) << name;
    }
  }
}

TEST_F(FilmOutputTest, PreviewsHaveTheirSizesAndColours) {
  const Film film = filledFilm();
  const fs::path exr = folder_ / "shot.exr";
  const auto written = hylios::writeFilmOutputs(film, exr);
  const fs::path visiblePng = folder_ / "shot_visible.png", uvPng = folder_ / "shot_uv365.png",
                 irPng = folder_ / "shot_ir1100.png";
  for (const auto& path : {visiblePng, uvPng, irPng})
    EXPECT_NE(std::find(written.begin(), written.end(), path), written.end()) << path;
  // Nothing else is left in the folder (no temporaries); sidecars only without text rendering.
  const std::set<fs::path> listed(written.begin(), written.end());
  EXPECT_EQ(folderContents(), listed);
  EXPECT_EQ(written.size(), hylios::textRenderingAvailable() ? 4u : 6u);

  const ReadImage visible = readImage(visiblePng);
  EXPECT_EQ(visible.spec.width, 4);
  EXPECT_EQ(visible.spec.height, 3);
  EXPECT_EQ(visible.spec.nchannels, 3);
  for (int x = 0; x < 4; ++x) {
    const double expected = hylios::srgbEncode(0.5 * grey(x));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(visible.at(x, 1, c), expected, 2.0 / 255) << x;
  }

  const ReadImage uv = readImage(uvPng);
  const int canvasWidth = hylios::kMinPseudoColourWidth;
  EXPECT_EQ(uv.spec.width, canvasWidth);
  EXPECT_EQ(uv.spec.height, 3 + hylios::colourBarStripHeight(canvasWidth));
  const int offsetX = (canvasWidth - 4) / 2;
  for (int x = 0; x < 4; ++x) {
    const auto expected = hylios::colourMap(uvValue(x) / 2.0);  // fixed range [0, 2]
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(uv.at(offsetX + x, 0, c), expected[c], 1.0 / 255) << x;
  }
  const ReadImage ir = readImage(irPng);
  for (int y = 0; y < 3; ++y) {
    const auto expected = hylios::colourMap(irValue(y));  // fixed range [0, 1]
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(ir.at(offsetX, y, c), expected[c], 1.0 / 255) << y;
  }
}

TEST_F(FilmOutputTest, NonFiniteFilmIsAnErrorAndWritesNothing) {
  Film film = filledFilm();
  // Two huge finite samples overflow the channel's sum to +Inf.
  film.addSample(2, 1, 0, 1e308);
  film.addSample(2, 1, 0, 1e308);
  try {
    hylios::writeFilmOutputs(film, folder_ / "bad.exr");
    FAIL() << "a film with an infinite value was written";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("(2, 1)"), std::string::npos) << error.what();
  }
  EXPECT_TRUE(folderContents().empty());
}

TEST_F(FilmOutputTest, ValuesBeyondFloatAreAnError) {
  Film film = filledFilm();
  film.addSample(0, 0, 0, 1e300);  // finite double, infinite float
  EXPECT_THROW(hylios::writeFilmOutputs(film, folder_ / "big.exr"), std::runtime_error);
  EXPECT_TRUE(folderContents().empty());
}

TEST_F(FilmOutputTest, GreyRgbWithoutAColourBand) {
  FilmDesc desc = testDesc();
  desc.bands = {singleBand("uv365", 365, 0.0, 2.0)};
  Film film(desc);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) film.addSample(x, y, 0, uvValue(x));
  const fs::path exr = folder_ / "uv.exr";
  hylios::writeFilmOutputs(film, exr);
  const ReadImage image = readImage(exr);
  for (int c = 0; c < image.spec.nchannels; ++c) {
    if (hylios::parseSpectralChannelName(image.spec.channelnames[c])) continue;
    for (int x = 0; x < 4; ++x) EXPECT_FLOAT_EQ(image.at(x, 2, c), static_cast<float>(uvValue(x)));
  }
}

TEST_F(FilmOutputTest, ContactSheetGridAndErrors) {
  const Film film = filledFilm();
  hylios::writeFilmOutputs(film, folder_ / "shot.exr");
  const std::vector<fs::path> panels{folder_ / "shot_uv365.png", folder_ / "shot_ir1100.png",
                                     folder_ / "shot_visible.png"};
  const fs::path sheet = folder_ / "sheet.png";
  hylios::writeContactSheet(panels, {"UV 365 nm", "IR 1100 nm", "visible"}, sheet, 2);
  const ReadImage image = readImage(sheet);
  const ReadImage panel = readImage(panels[0]);
  EXPECT_GE(image.spec.width, 2 * panel.spec.width);  // two columns of the widest panel
  EXPECT_LT(image.spec.width, 3 * panel.spec.width);
  EXPECT_GE(image.spec.height, 2 * panel.spec.height);  // two rows
  EXPECT_EQ(fs::exists(folder_ / "sheet.labels.txt"), !hylios::textRenderingAvailable());

  EXPECT_THROW(hylios::writeContactSheet(panels, {"one"}, folder_ / "x.png", 2),
               std::invalid_argument);
  EXPECT_THROW(hylios::writeContactSheet(panels, {"a", "b", "c"}, folder_ / "x.png", 0),
               std::invalid_argument);
  EXPECT_THROW(hylios::writeContactSheet({folder_ / "missing.png"}, {"m"}, folder_ / "x.png", 1),
               std::runtime_error);
  EXPECT_FALSE(fs::exists(folder_ / "x.png"));
}

TEST(PreviewText, LabelsAreDrawnWhenTextIsAvailable) {
  if (!hylios::textRenderingAvailable()) GTEST_SKIP() << "OpenImageIO cannot render text here";
  hylios::RgbCanvas canvas = hylios::makeCanvas(80, 30);
  ASSERT_TRUE(hylios::drawText(canvas, 40, 22, "0.25", 16, hylios::TextAnchor::Centre));
  float maximum = 0;
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 80; ++x) maximum = std::max(maximum, canvas.pixel(x, y)[0]);
  EXPECT_GT(maximum, 0.5f);
}

}  // namespace
