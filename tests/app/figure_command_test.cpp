// `hylios figure` (app/figure_job.h) on the paper's Figure 13 at 24 × 24, 2 spp: the contact
// sheet's panels come in the order of the varied quantity whatever the order on the command line,
// with its captions, a title and the pseudo-colour scale; the ground behind the head is black
// (camera_visible = false); the panel means and their standard errors are those of the film.
// And the gallery report (app/gallery_report.h) on made-up means: what it says of each trend.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <unistd.h>
#include <vector>

#include "app/commands.h"
#include "app/figure_job.h"
#include "app/gallery_report.h"
#include "app/paper_figures.h"

namespace hylios {
namespace {

namespace fs = std::filesystem;

const fs::path kScenes = fs::path(HYLIOS_SOURCE_DIR) / "scenes";

struct Scratch {
  fs::path path = fs::temp_directory_path() / ("hylios-figure-" + std::to_string(::getpid()));
  Scratch() { fs::create_directories(path); }
  ~Scratch() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

/// One channel of an EXR as floats, with its width.
std::vector<float> readChannel(const fs::path& exr, const std::string& name, int& width) {
  auto in = OIIO::ImageInput::open(exr.string());
  EXPECT_TRUE(in) << exr;
  if (!in) return {};
  const OIIO::ImageSpec& spec = in->spec();
  width = spec.width;
  int channel = -1;
  for (int c = 0; c < spec.nchannels; ++c)
    if (spec.channelnames[c] == name) channel = c;
  EXPECT_GE(channel, 0) << name;
  std::vector<float> values(static_cast<std::size_t>(spec.width) * spec.height);
  in->read_image(0, 0, channel, channel + 1, OIIO::TypeDesc::FLOAT, values.data());
  return values;
}

TEST(FigureCommand, Figure13PanelsInMelaninOrderWithCaptionsOnBlack) {
  const Scratch scratch;
  RenderSettings settings;
  settings.width = settings.height = 24;
  settings.samplesPerPixel = 2;
  settings.threads = 2;
  // The shell's order: 1.5, 30, 7.
  const FigureResult figure = renderFigure({(kScenes / "figure13_melanin1.5.toml").string(),
                                            (kScenes / "figure13_melanin30.toml").string(),
                                            (kScenes / "figure13_melanin7.toml").string()},
                                           scratch.path, settings, nullptr);
  ASSERT_EQ(figure.panels.size(), 3u);
  const std::vector<std::string> captions = {"epidermal melanin 1.5 %", "epidermal melanin 7 %",
                                             "epidermal melanin 30 %"};
  const std::vector<std::string> stems = {"figure13_melanin1.5", "figure13_melanin7",
                                          "figure13_melanin30"};
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(figure.panels[i].caption, captions[i]);
    EXPECT_EQ(figure.panels[i].scene.stem().string(), stems[i]);
    EXPECT_EQ(figure.panels[i].preview, scratch.path / (stems[i] + "_uv365.png"));
    EXPECT_EQ(figure.panels[i].quantity, "radiance");
    EXPECT_EQ(figure.panels[i].samplesPerPixel, 2);
  }
  ASSERT_EQ(figure.titleLines.size(), 2u);
  EXPECT_EQ(figure.titleLines[0], "365 nm · specimen S1");
  EXPECT_EQ(figure.titleLines[1],
            "pseudo-colour: radiance 0 to 0.1 (relative: 1 = white diffuser, unit environment)");
  // One row of three panels under the title.
  auto sheet = OIIO::ImageInput::open(figure.sheet.string());
  ASSERT_TRUE(sheet);
  auto panel = OIIO::ImageInput::open(figure.panels[0].preview.string());
  ASSERT_TRUE(panel);
  EXPECT_GT(sheet->spec().width, 3 * panel->spec().width);
  EXPECT_LT(sheet->spec().width, 4 * panel->spec().width);
  EXPECT_GT(sheet->spec().height, panel->spec().height);

  // The ground: where no centre ray within two pixels meets the head (A = 0 around), the
  // radiance is exactly 0, though the environment (0.15) lights the head; seen, it would be 0.15.
  int width = 0;
  const fs::path exr = scratch.path / "figure13_melanin1.5.exr";
  const auto radiance = readChannel(exr, "S0.365,000000nm", width);
  const auto alpha = readChannel(exr, "A", width);
  ASSERT_EQ(radiance.size(), alpha.size());
  const int height = static_cast<int>(alpha.size()) / width;
  auto clearAround = [&](int x, int y) {
    for (int dy = -2; dy <= 2; ++dy)
      for (int dx = -2; dx <= 2; ++dx) {
        const int u = std::clamp(x + dx, 0, width - 1), v = std::clamp(y + dy, 0, height - 1);
        if (alpha[static_cast<std::size_t>(v) * width + u] != 0) return false;
      }
    return true;
  };
  std::size_t background = 0;
  double sum = 0;
  std::size_t head = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t p = static_cast<std::size_t>(y) * width + x;
      if (alpha[p] != 0) {
        sum += radiance[p];
        ++head;
      } else if (clearAround(x, y)) {
        ++background;
        EXPECT_EQ(radiance[p], 0.0f) << "pixel (" << x << ", " << y << ")";
      }
    }
  EXPECT_GT(background, 30u);
  ASSERT_GT(head, 50u);
  // The panel's mean is the mean of the film over the head pixels (the EXR holds it as float).
  EXPECT_EQ(figure.panels[0].head.pixels, head);
  EXPECT_NEAR(figure.panels[0].head.mean, sum / static_cast<double>(head),
              1e-5 * figure.panels[0].head.mean);
  // Its standard error: at 2 spp per-pixel noise is of order 100 %, so SE ≈ mean / √N within a
  // factor 3 either way.
  const double rough = figure.panels[0].head.mean / std::sqrt(static_cast<double>(head));
  EXPECT_GT(figure.panels[0].head.standardError, rough / 3);
  EXPECT_LT(figure.panels[0].head.standardError, rough * 3);
}

TEST(FigureCommand, RefusesTwoScenesWithOneStem) {
  const Scratch scratch;
  fs::create_directories(scratch.path / "a");
  fs::copy_file(kScenes / "figure13_melanin7.toml", scratch.path / "a" / "figure13_melanin7.toml");
  EXPECT_THROW(renderFigure({(kScenes / "figure13_melanin7.toml").string(),
                             (scratch.path / "a" / "figure13_melanin7.toml").string()},
                            scratch.path / "out", RenderSettings{}, nullptr),
               std::invalid_argument);
  EXPECT_FALSE(fs::exists(scratch.path / "out"));
}

/// A figure of three panels with the given means (standard error 0.001 each).
GalleryFigure madeUp(int number, const std::vector<double>& means) {
  GalleryFigure figure;
  for (const PaperFigure& f : paperFigures())
    if (f.number == number) figure.paper = f;
  for (std::size_t i = 0; i < means.size(); ++i) {
    FigurePanel p;
    p.caption = "panel " + std::to_string(i + 1);
    p.quantity = "radiance";
    p.head.mean = means[i];
    p.head.standardError = 0.001;
    p.head.pixels = 1000;
    figure.result.panels.push_back(p);
  }
  figure.sheetImage = "figures/figure" + std::to_string(number) + ".png";
  return figure;
}

TEST(GalleryReport, TrendVerdicts) {
  const GalleryFigure darker = madeUp(12, {0.3, 0.2, 0.1});
  EXPECT_NE(trendVerdict(darker, {darker}).find("Every step is darker"), std::string::npos);
  // 0.2 → 0.199 is within 3 standard errors: not "every step darker".
  const GalleryFigure flat = madeUp(12, {0.3, 0.2, 0.199});
  EXPECT_NE(trendVerdict(flat, {flat}).find("do **not** follow"), std::string::npos);
  const GalleryFigure brighter = madeUp(14, {0.1, 0.12, 0.15});
  EXPECT_NE(trendVerdict(brighter, {brighter}).find("Every step is brighter"), std::string::npos);
  EXPECT_NE(trendVerdict(brighter, {brighter}).find("+20.0 %"), std::string::npos);
  // Figure 13's last step (−1 %) against Figure 12's (−50 %).
  const GalleryFigure uv = madeUp(13, {0.05, 0.03, 0.0297});
  EXPECT_NE(trendVerdict(uv, {darker, uv}).find("less than half as much"), std::string::npos);
  const GalleryFigure uvSteep = madeUp(13, {0.05, 0.03, 0.01});
  EXPECT_NE(trendVerdict(uvSteep, {darker, uvSteep}).find("**not** much less"), std::string::npos);
  // Figure 1: freckle contrast per panel, UV against IR.
  GalleryFigure freckles = madeUp(1, {0.05, 0.12, 0.26});
  freckles.result.panels[0].freckles = FreckleContrast{0.3, 0.02, 100, 5000};
  freckles.result.panels[2].freckles = FreckleContrast{0.01, 0.02, 100, 5000};
  EXPECT_NE(trendVerdict(freckles, {freckles}).find("stand out more in the UV"), std::string::npos);
  const std::string md = galleryMarkdown({freckles, darker}, GalleryRun{});
  EXPECT_NE(md.find("## Figure 1: "), std::string::npos);
  EXPECT_NE(md.find("![Figure 12](figures/figure12.png)"), std::string::npos);
  EXPECT_NE(md.find("| panel 1 |"), std::string::npos);
}

}  // namespace
}  // namespace hylios
