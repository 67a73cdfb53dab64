// `hylios render` as a child process, interrupted by real signals: SIGINT after the first sample
// pass is reported → exit status 130, a readable EXR with hylios:spp < hylios:sppTarget and a
// checkpoint; a damaged or foreign checkpoint is refused and nothing is overwritten; --resume,
// itself interrupted by SIGTERM (143) and resumed again, ends with the pixels of an uninterrupted
// render (other thread count) and removes the checkpoint.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <poll.h>
#include <string>
#include <unistd.h>
#include <vector>

#include "tests/support/file_bytes.h"

namespace fs = std::filesystem;

namespace {

struct ChildResult {
  int exitStatus = -1;  ///< WEXITSTATUS, or -1 when killed by a signal / timed out
  std::string out;      ///< stdout
  std::string err;      ///< stderr
  bool signalled = false;
};

using hylios::test::readBytes;

/// The scene both tests render.
const std::string kTestScene =
    (fs::path(HYLIOS_SOURCE_DIR) / "scenes/test/skin_sphere_550.toml").string();

/// `name` under the build folder, emptied (removed and made again).
fs::path freshFolder(const std::string& name) {
  const fs::path folder = fs::path(HYLIOS_BINARY_DIR) / name;
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

/// Runs hylios with `args`; when `signal` is non-zero, sends it once stdout has a line containing
/// "pass done" (the render reported its first sample pass). Gives up after 120 s.
ChildResult runHylios(const std::vector<std::string>& args, int signal = 0) {
  const fs::path binary = fs::path(HYLIOS_BINARY_DIR) / "hylios";
  // Per test process: CTest runs the tests of this file in parallel.
  const fs::path errFile = fs::temp_directory_path() /
                           ("hylios-render-interrupt-" + std::to_string(::getpid()) + ".err");
  int pipeFds[2];
  if (::pipe(pipeFds) != 0) throw std::runtime_error("pipe failed");
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    ::dup2(pipeFds[1], STDOUT_FILENO);
    std::FILE* err = std::freopen(errFile.c_str(), "w", stderr);
    (void)err;
    ::close(pipeFds[0]);
    ::close(pipeFds[1]);
    std::vector<char*> argv{const_cast<char*>(binary.c_str())};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(binary.c_str(), argv.data());
    ::_exit(127);
  }
  ::close(pipeFds[1]);
  ChildResult result;
  bool sent = signal == 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  for (;;) {
    pollfd fd{pipeFds[0], POLLIN, 0};
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      break;
    }
    if (::poll(&fd, 1, 1000) <= 0) continue;
    char buffer[4096];
    const ssize_t n = ::read(pipeFds[0], buffer, sizeof buffer);
    if (n <= 0) break;
    result.out.append(buffer, static_cast<std::size_t>(n));
    if (!sent && result.out.find("pass done") != std::string::npos) {
      ::kill(pid, signal);
      sent = true;
    }
  }
  ::close(pipeFds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (WIFEXITED(status)) result.exitStatus = WEXITSTATUS(status);
  result.signalled = WIFSIGNALED(status);
  result.err = readBytes(errFile);
  return result;
}

struct Exr {
  int spp = -1, sppTarget = -1;
  std::vector<float> pixels;
  std::vector<std::string> channels;
};

Exr readExr(const fs::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) throw std::runtime_error("cannot open " + path.string() + ": " + OIIO::geterror());
  Exr exr;
  exr.spp = in->spec().get_int_attribute("hylios:spp", -1);
  exr.sppTarget = in->spec().get_int_attribute("hylios:sppTarget", -1);
  exr.channels = in->spec().channelnames;
  exr.pixels.resize(static_cast<std::size_t>(in->spec().image_pixels()) * in->spec().nchannels);
  if (!in->read_image(0, 0, 0, in->spec().nchannels, OIIO::TypeDesc::FLOAT, exr.pixels.data()))
    throw std::runtime_error("cannot read " + path.string());
  return exr;
}

}  // namespace

TEST(RenderInterrupt, SignalsSaveACheckpointAndResumeGivesTheUninterruptedImage) {
  const fs::path folder = freshFolder("render_interrupt_test");
  ASSERT_TRUE(fs::exists(fs::path(HYLIOS_BINARY_DIR) / "hylios"))
      << "build the hylios target first";
  const std::string scene = kTestScene;
  // ~0.5 s of rendering on two cores; the first pass (1 spp) is reported after ~1/64 of it, so the
  // signal arrives long before the end.
  const std::vector<std::string> common = {"render",       scene,   "--spp",  "64",
                                           "--resolution", "64x64", "--seed", "5"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = common;
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  };
  const std::string out = (folder / "shot.exr").string();
  const fs::path state = out + ".hylios-state";

  // 1. SIGINT after the first pass.
  const ChildResult interrupted = runHylios(with({"--out", out, "--threads", "2"}), SIGINT);
  ASSERT_EQ(interrupted.exitStatus, 130) << interrupted.out << interrupted.err;
  EXPECT_NE(interrupted.err.find("interrupted by SIGINT"), std::string::npos) << interrupted.err;
  ASSERT_TRUE(fs::exists(state));
  const Exr partial = readExr(out);
  EXPECT_GT(partial.spp, 0);
  EXPECT_LT(partial.spp, 64);
  EXPECT_EQ(partial.sppTarget, 64);
  for (const float v : partial.pixels) ASSERT_TRUE(std::isfinite(v));

  // 2. A foreign checkpoint (another seed, other options) and a damaged one are refused; nothing
  //    is overwritten.
  const std::string exrBytes = readBytes(out), stateBytes = readBytes(state);
  const ChildResult foreign = runHylios({"render", scene, "--spp", "64", "--resolution", "64x64",
                                         "--seed", "6", "--out", out, "--resume"});
  EXPECT_EQ(foreign.exitStatus, 1);
  EXPECT_NE(foreign.err.find("seed: checkpoint 5, this run 6"), std::string::npos) << foreign.err;
  const ChildResult otherOptions = runHylios(with({"--out", out, "--resume", "--epsilon", "0.01"}));
  EXPECT_EQ(otherOptions.exitStatus, 1);
  EXPECT_NE(otherOptions.err.find("options: checkpoint '', this run '--epsilon=0.01'"),
            std::string::npos)
      << otherOptions.err;
  std::string damaged = stateBytes;
  damaged[damaged.size() / 2] = static_cast<char>(damaged[damaged.size() / 2] ^ 1);
  std::ofstream(state, std::ios::binary) << damaged;
  const ChildResult corrupt = runHylios(with({"--out", out, "--resume"}));
  EXPECT_EQ(corrupt.exitStatus, 1);
  EXPECT_NE(corrupt.err.find("checksum"), std::string::npos) << corrupt.err;
  EXPECT_TRUE(readBytes(out) == exrBytes);
  EXPECT_TRUE(readBytes(state) == damaged);
  std::ofstream(state, std::ios::binary) << stateBytes;

  // 3. Resume, interrupted again (SIGTERM) after its first pass, then resumed to the end.
  const ChildResult again = runHylios(with({"--out", out, "--threads", "1", "--resume"}), SIGTERM);
  ASSERT_EQ(again.exitStatus, 143) << again.out << again.err;
  const Exr further = readExr(out);
  EXPECT_GT(further.spp, partial.spp);
  EXPECT_LT(further.spp, 64);
  const ChildResult finished = runHylios(with({"--out", out, "--threads", "1", "--resume"}));
  ASSERT_EQ(finished.exitStatus, 0) << finished.out << finished.err;
  EXPECT_FALSE(fs::exists(state));
  EXPECT_FALSE(fs::exists(fs::path(out + ".tmp-" + std::to_string(::getpid()))));

  // 4. The uninterrupted render (two threads): the same pixels, bit for bit.
  const std::string whole = (folder / "whole.exr").string();
  const ChildResult uninterrupted = runHylios(with({"--out", whole, "--threads", "2"}));
  ASSERT_EQ(uninterrupted.exitStatus, 0) << uninterrupted.err;
  const Exr resumed = readExr(out), reference = readExr(whole);
  EXPECT_EQ(resumed.spp, 64);
  EXPECT_EQ(reference.spp, 64);
  EXPECT_EQ(resumed.channels, reference.channels);
  ASSERT_EQ(resumed.pixels.size(), reference.pixels.size());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < resumed.pixels.size(); ++i)
    differing += resumed.pixels[i] != reference.pixels[i];
  EXPECT_EQ(differing, 0u) << "of " << resumed.pixels.size() << " values";
}

// Issue 13 row 12: after an interrupted render, the same command without --resume neither
// deletes the checkpoint nor overwrites the partial image; it says how to resume or discard.
TEST(RenderInterrupt, RerunningWithoutResumeKeepsTheCheckpointAndSaysHowToGoOn) {
  const fs::path folder = freshFolder("render_interrupt_keep_test");
  ASSERT_TRUE(fs::exists(fs::path(HYLIOS_BINARY_DIR) / "hylios"))
      << "build the hylios target first";
  const std::string scene = kTestScene;
  const std::string out = (folder / "kept.exr").string();
  const fs::path state = out + ".hylios-state";
  fs::remove(out);
  fs::remove(state);
  const std::vector<std::string> args = {"render", scene, "--spp", "64", "--resolution", "64x64",
                                         "--seed", "5",   "--out", out,  "--threads",    "2"};
  const ChildResult interrupted = runHylios(args, SIGINT);
  ASSERT_EQ(interrupted.exitStatus, 130) << interrupted.out << interrupted.err;
  ASSERT_TRUE(fs::exists(state));
  const std::string exrBytes = readBytes(out), stateBytes = readBytes(state);
  const ChildResult rerun = runHylios(args);
  EXPECT_EQ(rerun.exitStatus, 1) << rerun.out << rerun.err;
  EXPECT_NE(rerun.err.find("--resume"), std::string::npos) << rerun.err;
  EXPECT_NE(rerun.err.find("delete that file"), std::string::npos) << rerun.err;
  EXPECT_EQ(rerun.out.find("pass done"), std::string::npos) << "it rendered: " << rerun.out;
  EXPECT_TRUE(readBytes(state) == stateBytes);
  EXPECT_TRUE(readBytes(out) == exrBytes);
}
