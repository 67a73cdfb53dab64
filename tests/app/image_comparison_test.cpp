// Image comparison (renderer/image/image_comparison.h) and `hylios image-diff`: relative RMSE,
// relative bias and block means on small hand-computed EXRs; clear errors for mismatched images.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/commands.h"
#include "renderer/image/image_comparison.h"
#include "tests/support/scratch_csv.h"

namespace {

namespace fs = std::filesystem;
using hylios::ExrImage;

const std::string k500 = "S0.500,000000nm";
const std::string k600 = "S0.600,000000nm";

/// An image from per-channel planes (planes[c][y·width + x]).
ExrImage makeImage(int width, int height, const std::vector<std::string>& names,
                   const std::vector<std::vector<float>>& planes) {
  ExrImage image;
  image.width = width;
  image.height = height;
  image.channelNames = names;
  image.pixels.resize(static_cast<std::size_t>(width) * height * names.size());
  for (std::size_t c = 0; c < names.size(); ++c)
    for (std::size_t p = 0; p < static_cast<std::size_t>(width) * height; ++p)
      image.pixels[p * names.size() + c] = planes[c][p];
  return image;
}

void writeExr(const ExrImage& image, const fs::path& path) {
  auto out = OIIO::ImageOutput::create("openexr");
  ASSERT_TRUE(out);
  OIIO::ImageSpec spec(image.width, image.height, static_cast<int>(image.channelNames.size()),
                       OIIO::TypeDesc::FLOAT);
  spec.channelnames = image.channelNames;
  ASSERT_TRUE(out->open(path.string(), spec)) << out->geterror();
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data())) << out->geterror();
  ASSERT_TRUE(out->close());
}

// 2x2 pixels. 500 nm: reference 1,2,3,2 (mean |b| = 2), test 2,2,3,1 (differences 1,0,0,-1):
// RMSE = sqrt(2/4), relative 0.353553, bias 0. 600 nm: reference 4 everywhere, test 5: RMSE 1,
// relative 0.25, bias +0.25. R: reference 1, test 0: relative 1, bias -1 (not in "overall").
// Overall over 500 and 600 nm: RMSE = sqrt(6/8), mean |b| = 24/8 = 3, relative 0.288675, bias
// (4/8)/3 = 0.166667.
ExrImage referenceTwoByTwo() {
  return makeImage(2, 2, {k500, k600, "R"}, {{1, 2, 3, 2}, {4, 4, 4, 4}, {1, 1, 1, 1}});
}
ExrImage testTwoByTwo() {
  return makeImage(2, 2, {k500, k600, "R"}, {{2, 2, 3, 1}, {5, 5, 5, 5}, {0, 0, 0, 0}});
}

TEST(ImageComparison, RelativeRmseAndBiasPerChannelAndPooledOverSpectralChannels) {
  const auto result = hylios::compareImages(testTwoByTwo(), "test", referenceTwoByTwo(), "ref", 1);
  ASSERT_EQ(result.channels.size(), 3u);
  EXPECT_EQ(result.channels[0].channel, k500);
  ASSERT_TRUE(result.channels[0].wavelengthNm.has_value());
  EXPECT_DOUBLE_EQ(*result.channels[0].wavelengthNm, 500.0);
  EXPECT_EQ(result.channels[0].valuesCompared, 4u);
  EXPECT_NEAR(result.channels[0].rmse, std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(result.channels[0].referenceMeanAbs, 2.0, 1e-12);
  EXPECT_NEAR(result.channels[0].relativeRmse, std::sqrt(0.5) / 2, 1e-12);
  EXPECT_NEAR(result.channels[0].meanRelativeDifference, 0.0, 1e-12);
  EXPECT_NEAR(result.channels[1].relativeRmse, 0.25, 1e-12);
  EXPECT_NEAR(result.channels[1].meanRelativeDifference, 0.25, 1e-12);
  EXPECT_FALSE(result.channels[2].wavelengthNm.has_value());
  EXPECT_NEAR(result.channels[2].relativeRmse, 1.0, 1e-12);
  EXPECT_NEAR(result.channels[2].meanRelativeDifference, -1.0, 1e-12);
  EXPECT_EQ(result.overallChannelCount, 2u);
  EXPECT_EQ(result.overall.valuesCompared, 8u);
  EXPECT_NEAR(result.overall.rmse, std::sqrt(0.75), 1e-12);
  EXPECT_NEAR(result.overall.referenceMeanAbs, 3.0, 1e-12);
  EXPECT_NEAR(result.overall.relativeRmse, std::sqrt(0.75) / 3, 1e-12);
  EXPECT_NEAR(result.overall.meanRelativeDifference, 0.5 / 3, 1e-12);
}

TEST(ImageComparison, IdenticalImagesHaveZeroError) {
  const auto result = hylios::compareImages(referenceTwoByTwo(), "a", referenceTwoByTwo(), "b", 2);
  EXPECT_EQ(result.overall.rmse, 0.0);
  EXPECT_EQ(result.overall.relativeRmse, 0.0);
  EXPECT_EQ(result.overall.meanRelativeDifference, 0.0);
}

TEST(ImageComparison, ChannelsAreMatchedByNameAndWithoutSpectralChannelsAllArePooled) {
  // Reference stores G before R; test R = 2, G = 2; reference R = 1, G = 3. Overall over both:
  // differences +1 and -1, RMSE 1, mean |b| = 2, relative 0.5, bias 0.
  const ExrImage test = makeImage(1, 1, {"R", "G"}, {{2}, {2}});
  const ExrImage reference = makeImage(1, 1, {"G", "R"}, {{3}, {1}});
  const auto result = hylios::compareImages(test, "t", reference, "r", 1);
  EXPECT_NEAR(result.channels[0].relativeRmse, 1.0, 1e-12);        // R: |2-1| / 1
  EXPECT_NEAR(result.channels[1].relativeRmse, 1.0 / 3.0, 1e-12);  // G: |2-3| / 3
  EXPECT_EQ(result.overallChannelCount, 2u);
  EXPECT_NEAR(result.overall.relativeRmse, 0.5, 1e-12);
  EXPECT_NEAR(result.overall.meanRelativeDifference, 0.0, 1e-12);
}

// 5x3 pixels, block 2: two whole blocks (x 0-1 and 2-3, y 0-1); column 4 and row 2 are left out
// (they hold a difference of 100 that must not count). Reference 1 everywhere. Test block 0 is
// 1.5, 0.5 / 0.5, 1.5 (mean 1: the pixel noise cancels), block 1 is 1.5 everywhere. Block means
// 1 and 1.5: RMSE sqrt(0.25/2) = 0.353553, bias 0.25. Pixels in the 4x2 part: differences ±0.5
// and 0.5, RMSE 0.5 (with the strips it would be far larger).
ExrImage blockTest() {
  std::vector<float> plane(15, 101.0f);
  const float inner[2][4] = {{1.5f, 0.5f, 1.5f, 1.5f}, {0.5f, 1.5f, 1.5f, 1.5f}};
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) plane[static_cast<std::size_t>(y * 5 + x)] = inner[y][x];
  return makeImage(5, 3, {k500}, {plane});
}

TEST(ImageComparison, BlockMeansRemoveCancellingPixelNoiseAndSkipPartialBlocks) {
  const ExrImage reference = makeImage(5, 3, {k500}, {std::vector<float>(15, 1.0f)});
  const auto blocks = hylios::compareImages(blockTest(), "t", reference, "r", 2);
  EXPECT_EQ(blocks.blocksX, 2);
  EXPECT_EQ(blocks.blocksY, 1);
  EXPECT_EQ(blocks.overall.valuesCompared, 2u);
  EXPECT_NEAR(blocks.overall.rmse, std::sqrt(0.125), 1e-7);
  EXPECT_NEAR(blocks.overall.meanRelativeDifference, 0.25, 1e-7);
  const auto pixels = hylios::compareImages(blockTest(), "t", reference, "r", 1);
  EXPECT_EQ(pixels.overall.valuesCompared, 15u);
  EXPECT_GT(pixels.overall.rmse, 10.0);  // the strips count at block size 1
}

TEST(ImageComparison, MismatchedImagesAreClearErrors) {
  const ExrImage small = makeImage(1, 2, {k500}, {{1, 1}});
  try {
    hylios::compareImages(small, "a.exr", referenceTwoByTwo(), "b.exr", 1);
    FAIL() << "size mismatch accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'a.exr' is 1x2, 'b.exr' is 2x2"), std::string::npos)
        << e.what();
  }
  const ExrImage other =
      makeImage(2, 2, {k500, "S0.700,000000nm", "R"}, {{1, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 1}});
  try {
    hylios::compareImages(other, "a.exr", referenceTwoByTwo(), "b.exr", 1);
    FAIL() << "channel mismatch accepted";
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("'a.exr' has S0.700,000000nm which 'b.exr' lacks"), std::string::npos)
        << message;
    EXPECT_NE(message.find("'b.exr' has S0.600,000000nm which 'a.exr' lacks"), std::string::npos)
        << message;
  }
  EXPECT_THROW(hylios::compareImages(testTwoByTwo(), "a", referenceTwoByTwo(), "b", 3),
               std::invalid_argument);
  EXPECT_THROW(hylios::compareImages(testTwoByTwo(), "a", referenceTwoByTwo(), "b", 0),
               std::invalid_argument);
}

TEST(ImageComparison, ZeroReferenceChannelIsAnErrorNamingIt) {
  const ExrImage reference = makeImage(1, 1, {k500, k600}, {{1}, {0}});
  const ExrImage test = makeImage(1, 1, {k500, k600}, {{1}, {1}});
  try {
    hylios::compareImages(test, "t", reference, "ref.exr", 1);
    FAIL() << "zero reference accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'ref.exr': channel " + k600 + " is zero everywhere"),
              std::string::npos)
        << e.what();
  }
}

TEST(ImageComparison, ReadsExrFilesAndRejectsUnreadableOrNonFiniteOnes) {
  hylios::test::ScratchFolder scratch("image-comparison");
  writeExr(testTwoByTwo(), scratch.path / "test.exr");
  writeExr(referenceTwoByTwo(), scratch.path / "ref.exr");
  const ExrImage read = hylios::readExrImage(scratch.path / "ref.exr");
  EXPECT_EQ(read.width, 2);
  // OpenEXR stores channels sorted by name: look them up.
  EXPECT_EQ(read.channelNames, (std::vector<std::string>{"R", k500, k600}));
  EXPECT_EQ(read.value(1, 1, 1), 2.0f);  // 500 nm at (1, 1)
  EXPECT_EQ(read.value(0, 1, 2), 4.0f);  // 600 nm at (0, 1)
  const auto result =
      hylios::compareImageFiles(scratch.path / "test.exr", scratch.path / "ref.exr", 1);
  EXPECT_NEAR(result.overall.relativeRmse, std::sqrt(0.75) / 3, 1e-7);
  try {
    hylios::readExrImage(scratch.path / "missing.exr");
    FAIL() << "missing file accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("missing.exr"), std::string::npos) << e.what();
  }
  ExrImage bad = referenceTwoByTwo();
  bad.pixels[4] = std::numeric_limits<float>::quiet_NaN();  // pixel (1, 0), 600 nm
  writeExr(bad, scratch.path / "nan.exr");
  try {
    hylios::readExrImage(scratch.path / "nan.exr");
    FAIL() << "NaN accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("pixel (1, 0), channel " + k600), std::string::npos)
        << e.what();
  }
}

TEST(ImageDiffCommand, WritesCsvWithOneRowPerChannelAndOverall) {
  hylios::test::ScratchFolder scratch("image-diff-command");
  writeExr(testTwoByTwo(), scratch.path / "test.exr");
  writeExr(referenceTwoByTwo(), scratch.path / "ref.exr");
  const fs::path csv = scratch.path / "diff.csv";
  hylios::test::runCommandLine(hylios::registerImageDiffCommand,
                               "image-diff " + (scratch.path / "test.exr").string() + " " +
                                   (scratch.path / "ref.exr").string() + " --csv " + csv.string());
  const auto rows = hylios::test::readCsv(csv);
  ASSERT_EQ(rows.size(), 5u);
  const auto& header = rows[0];
  const std::size_t relative = hylios::test::columnOf(header, "relative_rmse");
  const std::size_t bias = hylios::test::columnOf(header, "mean_relative_difference");
  ASSERT_LT(relative, header.size());
  ASSERT_LT(bias, header.size());
  // Rows in the file's channel order (OpenEXR sorts by name: R first), then overall.
  EXPECT_EQ(rows[1][0], "R");
  EXPECT_EQ(rows[1][1], "");
  EXPECT_NEAR(std::stod(rows[1][relative]), 1.0, 1e-6);
  // Spectral channel names hold a comma: quoted, so the row reads as 7 fields in a CSV reader.
  std::ifstream in(csv);
  std::string line;
  for (int i = 0; i < 3; ++i) std::getline(in, line);
  EXPECT_EQ(line, "\"" + k500 + "\",500,4,0.707107,2,0.353553,0");
  EXPECT_EQ(rows[4][0], "overall");
  EXPECT_NEAR(std::stod(rows[4][relative]), std::sqrt(0.75) / 3, 1e-5);
  EXPECT_NEAR(std::stod(rows[4][bias]), 0.5 / 3, 1e-5);
}

TEST(ImageDiffCommand, MismatchedFilesFailAndWriteNothing) {
  hylios::test::ScratchFolder scratch("image-diff-mismatch");
  writeExr(testTwoByTwo(), scratch.path / "test.exr");
  writeExr(makeImage(1, 1, {k500, k600, "R"}, {{1}, {1}, {1}}), scratch.path / "small.exr");
  const fs::path csv = scratch.path / "diff.csv";
  EXPECT_THROW(hylios::test::runCommandLine(hylios::registerImageDiffCommand,
                                            "image-diff " + (scratch.path / "test.exr").string() +
                                                " " + (scratch.path / "small.exr").string() +
                                                " --csv " + csv.string()),
               std::invalid_argument);
  EXPECT_FALSE(fs::exists(csv));
}

}  // namespace
