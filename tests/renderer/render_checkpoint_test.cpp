// Interruptible renders: sample passes leave the film's sums bit-identical; a render stopped
// between passes, saved to a checkpoint (renderer/image/render_checkpoint.h), read back and
// continued (at another thread count) gives exactly the film of an uninterrupted render; the EXR of
// a stopped render records its spp; damaged or foreign checkpoints are refused, saying why.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>

#include "renderer/image/film_output.h"
#include "renderer/image/render_checkpoint.h"
#include "renderer/scene/scene_file.h"
#include "renderer/tracing/integrator.h"
#include "skin/core/thread_limit.h"
#include "tests/support/error_message.h"
#include "tests/support/test_scenes.h"

using namespace hylios;
namespace fs = std::filesystem;

namespace {

constexpr int kSpp = 12;

/// The skin sphere test scene at 24×24 with 4 channels (550 nm; 600–700 nm in 50 nm steps), so
/// the channel stratification (which depends on the spp target) matters.
SceneDesc testScene() {
  SceneDesc scene = test::skinSphereScene(24, kSpp);
  scene.film.bands.push_back(test::rangeBand("red", 600, 700, 50));
  return scene;
}

std::vector<double> wavelengthsOf(const SceneDesc& scene) {
  std::vector<double> nm;
  const Film film(scene.film);
  for (const FilmChannel& c : film.channels()) nm.push_back(c.wavelengthNm);
  return nm;
}

/// One integrator for every test (the skin walks' preparation is the slow part).
const Integrator& integrator() {
  static const SceneDesc scene = testScene();
  static const Integrator instance(scene, wavelengthsOf(scene));
  return instance;
}

Film render(int threads, int samplesPerPass, int stopAfterPasses = -1, Film* resumeFrom = nullptr) {
  const hylios::ThreadLimit limit(threads);
  Film film(testScene().film);
  film.setWholeBandSamples(integrator().estimator() == hylios::skin::Estimator::Spectral);
  if (resumeFrom)
    film.restoreState(resumeFrom->sums(), resumeFrom->counts(), resumeFrom->secondHalfSums(),
                      resumeFrom->secondHalfCounts(), resumeFrom->samplesPerPixelDone());
  RenderOptions options;
  options.samplesPerPass = samplesPerPass;
  int passes = 0;
  options.onPassDone = [&](int, double) { ++passes; };
  options.stopRequested = [&] { return stopAfterPasses >= 0 && passes >= stopAfterPasses; };
  integrator().render(film, options);
  return film;
}

/// The uninterrupted render: one pass, one thread.
const Film& reference() {
  static const Film film = render(1, kSpp);
  return film;
}

void expectSameFilm(const Film& a, const Film& b) {
  ASSERT_EQ(a.sums().size(), b.sums().size());
  EXPECT_EQ(a.samplesPerPixelDone(), b.samplesPerPixelDone());
  EXPECT_TRUE(a.counts() == b.counts());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < a.sums().size(); ++i)
    differing += a.sums()[i] != b.sums()[i];  // exact, bit for bit
  EXPECT_EQ(differing, 0u) << "of " << a.sums().size() << " sums";
}

fs::path scratch(const std::string& name) {
  const fs::path folder = fs::path(HYLIOS_BINARY_DIR) / "render_checkpoint_test";
  fs::create_directories(folder);
  return folder / name;
}

RenderIdentity identity() {
  RenderIdentity id = renderIdentity(testScene(), "--skin-model=walk");
  return id;
}

std::string readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

}  // namespace

TEST(RenderPasses, SumsAreBitIdenticalForAnyPassSize) {
  const Film& whole = reference();
  ASSERT_EQ(whole.samplesPerPixelDone(), kSpp);
  expectSameFilm(render(1, 1), whole);
  expectSameFilm(render(2, 5), whole);  // passes of 5, 5, 2
  expectSameFilm(render(2, 0), whole);  // adaptive
}

TEST(RenderPasses, StopBetweenPassesKeepsWholePasses) {
  const Film stopped = render(2, 4, 2);
  EXPECT_EQ(stopped.samplesPerPixelDone(), 8);
  for (int y = 0; y < stopped.height(); ++y)
    for (int x = 0; x < stopped.width(); ++x) {
      std::uint32_t samples = 0;  // each sample fills one channel, or a whole band (spectral)
      for (std::size_t b = 0; b < stopped.bandCount(); ++b)
        for (std::size_t c : stopped.bandChannels(b))
          if (!stopped.wholeBandSamples() || c == stopped.bandChannels(b).front())
            samples += stopped.sampleCount(x, y, c);
      ASSERT_EQ(samples, 8u) << "pixel (" << x << ", " << y << ")";
    }
  const Film none = render(1, 4, 0);
  EXPECT_EQ(none.samplesPerPixelDone(), 0);
}

TEST(RenderCheckpoint, StoppedRenderContinuedFromItsCheckpointEqualsUninterrupted) {
  for (const int threads : {1, 2}) {
    const Film stopped = render(threads, 3, 2);  // 6 of 12 spp
    ASSERT_EQ(stopped.samplesPerPixelDone(), 6);
    const fs::path exr = scratch("stopped_" + std::to_string(threads) + ".exr");
    writeFilmOutputs(stopped, exr, {{"hylios:seed", "1"}});
    const fs::path state = checkpointPathFor(exr);
    writeRenderCheckpoint(state, identity(), stopped);

    // The EXR of the stopped render: its spp, the target, finite values.
    auto in = OIIO::ImageInput::open(exr.string());
    ASSERT_TRUE(in) << OIIO::geterror();
    EXPECT_EQ(in->spec().get_int_attribute("hylios:spp"), 6);
    EXPECT_EQ(in->spec().get_int_attribute("hylios:sppTarget"), kSpp);
    EXPECT_EQ(in->spec().get_string_attribute("hylios:seed"), "1");
    std::vector<float> pixels(static_cast<std::size_t>(in->spec().image_pixels()) *
                              in->spec().nchannels);
    ASSERT_TRUE(
        in->read_image(0, 0, 0, in->spec().nchannels, OIIO::TypeDesc::FLOAT, pixels.data()));
    double total = 0;
    for (const float v : pixels) {
      ASSERT_TRUE(std::isfinite(v));
      total += v;
    }
    EXPECT_GT(total, 0.0);

    // Read back, continue at the other thread count: the uninterrupted film, bit for bit.
    const RenderCheckpoint saved = readMatchingCheckpoint(state, identity());
    EXPECT_EQ(saved.samplesPerPixelDone, 6);
    Film restored(testScene().film);
    restored.setWholeBandSamples(reference().wholeBandSamples());
    restored.restoreState(saved.sums, saved.counts, saved.secondHalfSums, saved.secondHalfCounts,
                          saved.samplesPerPixelDone);
    const Film continued = render(3 - threads, 0, -1, &restored);
    expectSameFilm(continued, reference());
  }
}

TEST(RenderCheckpoint, RoundTripKeepsIdentityAndState) {
  const Film stopped = render(2, 5, 1);
  const fs::path state = scratch("round_trip.hylios-state");
  writeRenderCheckpoint(state, identity(), stopped);
  const RenderCheckpoint saved = readRenderCheckpoint(state);
  EXPECT_TRUE(identityDifferences(saved.identity, identity()).empty());
  EXPECT_EQ(saved.identity.channelWavelengthsNm, (std::vector<double>{550, 600, 650, 700}));
  EXPECT_EQ(saved.identity.samplesPerPixelTarget, kSpp);
  EXPECT_EQ(saved.samplesPerPixelDone, 5);
  EXPECT_TRUE(saved.sums == stopped.sums());
  EXPECT_TRUE(saved.counts == stopped.counts());
}

TEST(RenderCheckpoint, DamagedFilesAreRefusedSayingWhy) {
  const Film stopped = render(2, 5, 1);
  const fs::path state = scratch("damaged.hylios-state");
  writeRenderCheckpoint(state, identity(), stopped);
  const std::string good = readBytes(state);

  EXPECT_NE(test::errorOf<std::runtime_error>([&] {
              readRenderCheckpoint(scratch("absent.hylios-state"));
            }).find("no render checkpoint"),
            std::string::npos);
  std::string flipped = good;
  flipped[good.size() / 2] = static_cast<char>(flipped[good.size() / 2] ^ 0x10);
  writeBytes(state, flipped);
  EXPECT_NE(
      test::errorOf<std::runtime_error>([&] { readRenderCheckpoint(state); }).find("checksum"),
      std::string::npos);
  writeBytes(state, good.substr(0, good.size() - 100));
  EXPECT_NE(
      test::errorOf<std::runtime_error>([&] { readRenderCheckpoint(state); }).find("checksum"),
      std::string::npos);
  writeBytes(state, good.substr(0, 30));
  EXPECT_NE(
      test::errorOf<std::runtime_error>([&] { readRenderCheckpoint(state); }).find("truncated"),
      std::string::npos);
  writeBytes(state, "P6\n24 24\n255\n" + good.substr(13));
  EXPECT_NE(test::errorOf<std::runtime_error>([&] {
              readRenderCheckpoint(state);
            }).find("not a hylios render checkpoint"),
            std::string::npos);
  std::string version = good;
  version[25] = 2;  // the u32 after the 25-byte magic: version 2 did not record the sampler
  writeBytes(state, version);
  EXPECT_NE(test::errorOf<std::runtime_error>([&] {
              readRenderCheckpoint(state);
            }).find("format version 2"),
            std::string::npos);
  writeBytes(state, good);
  EXPECT_EQ(readRenderCheckpoint(state).samplesPerPixelDone, 5);
}

TEST(RenderCheckpoint, ForeignCheckpointsAreRefusedNamingEachDifference) {
  const Film stopped = render(2, 5, 1);
  const fs::path state = scratch("foreign.hylios-state");
  writeRenderCheckpoint(state, identity(), stopped);
  RenderIdentity other = identity();
  other.seed = 7;
  other.samplesPerPixelTarget = 64;
  other.width = 32;
  other.options = "--skin-model=table";
  other.sceneContentHash ^= 1;
  other.channelWavelengthsNm.pop_back();
  other.sampler = "independent";
  const std::string message =
      test::errorOf<std::runtime_error>([&] { readMatchingCheckpoint(state, other); });
  for (const char* what :
       {"seed: checkpoint 1, this run 7", "spp target: checkpoint 12, this run 64",
        "resolution: checkpoint 24x24, this run 32x24", "options: checkpoint '--skin-model=walk'",
        "scene file contents", "channel wavelengths",
        "sampler: checkpoint sobol, this run independent"})
    EXPECT_NE(message.find(what), std::string::npos) << what << " missing in: " << message;
  EXPECT_TRUE(identityDifferences(identity(), identity()).empty());
}

TEST(RenderCheckpoint, IdentityHashesTheSceneFileBytes) {
  const fs::path a = scratch("scene_a.toml"), b = scratch("scene_b.toml");
  const std::string text = readBytes(fs::path(HYLIOS_SOURCE_DIR) / "scenes/test/furnace.toml");
  writeBytes(a, text);
  writeBytes(b, text + "\n# a comment\n");
  SceneDesc scene = testScene();
  scene.file = a;
  const RenderIdentity first = renderIdentity(scene, "");
  scene.file = b;
  const RenderIdentity second = renderIdentity(scene, "");
  EXPECT_NE(first.sceneContentHash, second.sceneContentHash);
  scene.file = scratch("missing.toml");
  EXPECT_THROW(renderIdentity(scene, ""), std::runtime_error);
}

TEST(FilmRestoreState, RejectsStateThatDoesNotFit) {
  const Film& whole = reference();
  Film film(testScene().film);
  film.setWholeBandSamples(whole.wholeBandSamples());
  std::vector<std::uint32_t> counts = whole.counts();
  EXPECT_THROW(
      film.restoreState(whole.sums(), counts, whole.secondHalfSums(), whole.secondHalfCounts(), kSpp - 1),
      std::invalid_argument);  // counts add up to 12
  counts[5] += 1;
  EXPECT_THROW(film.restoreState(whole.sums(), counts, whole.secondHalfSums(), whole.secondHalfCounts(), kSpp),
               std::invalid_argument);
  std::vector<double> sums = whole.sums();
  sums[3] = std::nan("");
  EXPECT_THROW(film.restoreState(sums, whole.counts(), whole.secondHalfSums(), whole.secondHalfCounts(), kSpp),
               std::invalid_argument);
  sums.pop_back();
  EXPECT_THROW(film.restoreState(sums, whole.counts(), whole.secondHalfSums(), whole.secondHalfCounts(), kSpp),
               std::invalid_argument);
  std::vector<std::uint32_t> odd = whole.secondHalfCounts();
  odd[7] = whole.counts()[7] + 1;  // more odd samples than samples
  EXPECT_THROW(film.restoreState(whole.sums(), whole.counts(), whole.secondHalfSums(), odd, kSpp),
               std::invalid_argument);
  film.restoreState(whole.sums(), whole.counts(), whole.secondHalfSums(), whole.secondHalfCounts(), kSpp);
  expectSameFilm(film, whole);
}
