// Issue 13, "hostile use": every subcommand refuses what would crash, give a silently wrong value
// or lose a file — before any work, with a message that says what is wrong. Commands run
// in-process; the rows of the issue are named in each test.
#include <CLI/CLI.hpp>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "app/commands.h"
#include "app/option_checks.h"
#include "app/render_options.h"
#include "app/wavelength_list.h"

namespace hylios {
namespace {

namespace fs = std::filesystem;

const fs::path kSource = HYLIOS_SOURCE_DIR;

/// A scratch folder of this test, removed afterwards.
struct Scratch {
  fs::path path;
  explicit Scratch(const std::string& name)
      : path(fs::temp_directory_path() /
             ("hylios-hostile-" + name + "-" + std::to_string(::getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~Scratch() {
    std::error_code ignored;
    fs::permissions(path, fs::perms::owner_all, fs::perm_options::add, ignored);
    fs::remove_all(path, ignored);
  }
  std::string operator/(const std::string& name) const { return (path / name).string(); }
};

/// Runs one command line ("slab", "--rays", ...) with every subcommand registered; returns the
/// error's message, or "" when it ran through.
std::string errorOf(const std::vector<std::string>& args) {
  CLI::App app;
  registerCoefficientsCommand(app);
  registerSlabCommand(app);
  registerSpectrumCommand(app);
  registerBrdfCommand(app);
  registerForwardProfileCommand(app);
  registerRadialProfileCommand(app);
  registerRenderCommand(app);
  registerFigureCommand(app);
  registerImageDiffCommand(app);
  registerFitCommand(app);
  registerValidateCommand(app);
  std::vector<const char*> argv{"hylios"};
  for (const std::string& a : args) argv.push_back(a.c_str());
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const std::exception& e) {
    return std::string(e.what()).empty() ? "(empty message)" : e.what();
  }
  return "";
}

std::string readAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

const std::vector<std::string> kSlab = {"slab", "--layer", "n=1.37,mua=1,mus=100,g=0.9,d=0.1",
                                        "--rays", "200"};

std::vector<std::string> slabWith(std::vector<std::string> extra) {
  std::vector<std::string> args = kSlab;
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

const std::string kScene = (kSource / "scenes/test/skin_sphere_550.toml").string();

// ---- row 3 ------------------------------------------------------------------------------------

TEST(HostileUse, Row3RadialProfileRefusesAMaxRadiusThatGivesNanOrInf) {
  const Scratch scratch("row3");
  for (const std::string radius : {"1e-300", "1e300", "0", "nan", "inf", "-1"}) {
    const std::string out = scratch / "r.csv";
    const std::string error =
        errorOf({"radial-profile", "--rays", "200", "--max-radius-cm", radius, "--out", out});
    EXPECT_NE(error.find("--max-radius-cm"), std::string::npos) << radius << ": " << error;
    EXPECT_FALSE(fs::exists(out)) << radius;
  }
  EXPECT_EQ(errorOf({"radial-profile", "--rays", "200", "--max-radius-cm", "0.2", "--bins", "10",
                     "--out", scratch / "ok.csv"}),
            "");
}

// ---- row 4 ------------------------------------------------------------------------------------

TEST(HostileUse, Row4NegativeOrOverflowingCountsAndSeedsAreRefusedEverywhere) {
  const Scratch scratch("row4");
  const std::string out = scratch / "s.csv";
  for (const std::string rays : {"-1", "18446744073709551614", "0", "1e3", "nan", " 5"}) {
    const std::string error = errorOf(slabWith({"--rays", rays, "--out", out}));
    EXPECT_NE(error.find("--rays"), std::string::npos) << rays << ": " << error;
  }
  for (const std::string seed : {"-1", "99999999999999999999999", "9223372036854775808", "1.5"}) {
    EXPECT_NE(errorOf(slabWith({"--seed", seed, "--out", out})).find("--seed"), std::string::npos)
        << seed;
    EXPECT_NE(
        errorOf({"spectrum", "--wavelengths", "550", "--rays", "10", "--seed", seed, "--out", out})
            .find("--seed"),
        std::string::npos)
        << seed;
    EXPECT_NE(
        errorOf({"render", kScene, "--seed", seed, "--out", scratch / "x.exr"}).find("--seed"),
        std::string::npos)
        << seed;
  }
  for (const std::string seed : {"-1", "99999999999999999999999"}) {
    EXPECT_NE(errorOf({"fit", "--measured", "m.csv:x", "--out", scratch / "f.toml", "--seed", seed})
                  .find("--seed"),
              std::string::npos);
    EXPECT_NE(errorOf({"validate", "--out", scratch / "v", "--seed", seed}).find("--seed"),
              std::string::npos);
  }
  EXPECT_NE(errorOf({"validate", "--out", scratch / "v", "--rays", "-1"}).find("--rays"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(errorOf(slabWith({"--seed", "9223372036854775807", "--out", out})),
            "");  // 2^63 - 1, as scene files
}

TEST(HostileUse, Row4EpsilonNanIsRefusedByRenderAndFigureLikeSpectrum) {
  const Scratch scratch("row4eps");
  for (const std::string command : {"render", "figure"}) {
    for (const std::string epsilon : {"nan", "inf", "-0.5"}) {
      const std::string error =
          errorOf({command, kScene, "--epsilon", epsilon, "--out", scratch / "x.exr"});
      EXPECT_NE(error.find("--epsilon"), std::string::npos)
          << command << " " << epsilon << ": " << error;
    }
  }
  EXPECT_NE(errorOf({"spectrum", "--epsilon", "nan", "--out", scratch / "s.csv"}).find("--epsilon"),
            std::string::npos);
  for (const std::string angle : {"nan", "inf"}) {
    EXPECT_NE(errorOf({"spectrum", "--angle", angle, "--out", scratch / "s.csv"}).find("--angle"),
              std::string::npos);
    EXPECT_NE(
        errorOf({"fit", "--measured", "m.csv:x", "--angle", angle, "--out", scratch / "f.toml"})
            .find("--angle"),
        std::string::npos);
  }
  EXPECT_NE(errorOf({"render", kScene, "--noise-target", "nan", "--out", scratch / "x.exr"})
                .find("--noise-target"),
            std::string::npos);
}

// ---- row 5 ------------------------------------------------------------------------------------

TEST(HostileUse, Row5ASymlinkOutputWritesItsTargetAndStaysALink) {
  const Scratch scratch("row5");
  const std::string target = scratch / "target.csv", link = scratch / "link.csv";
  std::ofstream(target) << "old\n";
  fs::create_symlink(target, link);
  ASSERT_EQ(errorOf(slabWith({"--out", link})), "");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
  EXPECT_NE(readAll(target).find("specular_reflectance"), std::string::npos);
}

TEST(HostileUse, Row5ARenderToACharacterDeviceWritesThroughItAndNoPreviewsBesideIt) {
  if (::geteuid() != 0) GTEST_SKIP() << "making a device node needs root";
  const Scratch scratch("row5dev");
  const std::string device = scratch / "null";
  ASSERT_EQ(::mknod(device.c_str(), S_IFCHR | 0666, makedev(1, 3)), 0);  // a second /dev/null
  ASSERT_EQ(errorOf({"render", kScene, "--out", device, "--spp", "1", "--resolution", "8x8"}), "");
  EXPECT_TRUE(fs::is_character_file(fs::symlink_status(device)));
  EXPECT_EQ(std::distance(fs::directory_iterator(scratch.path), fs::directory_iterator{}),
            1);  // no null_*.png
}

// ---- row 6 ------------------------------------------------------------------------------------

TEST(HostileUse, Row6AnOutputThatIsAnInputIsRefusedBeforeAnyWork) {
  const Scratch scratch("row6");
  // render x.toml --out x.toml
  const std::string scene = scratch / "x.toml";
  fs::copy_file(kScene, scene);
  const std::string sceneText = readAll(scene);
  EXPECT_NE(errorOf({"render", scene, "--out", scene}).find("refusing to overwrite an input"),
            std::string::npos);
  EXPECT_EQ(readAll(scene), sceneText);
  // ... also through another spelling of the same file
  EXPECT_NE(errorOf({"render", scene, "--out", scratch / "./x.toml"}).find("input"),
            std::string::npos);
  // render --out naming a file the scene reads (here its mesh)
  std::ofstream(scratch / "m.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  std::string withMesh = sceneText;
  withMesh.replace(
      withMesh.find("[[light]]"), 9,
      "[[shape]]\ntype = \"mesh\"\nfile = \"m.obj\"\nmaterial = \"skin\"\n\n[[light]]");
  std::ofstream(scratch / "mesh.toml") << withMesh;
  EXPECT_NE(
      errorOf({"render", scratch / "mesh.toml", "--out", scratch / "m.obj"}).find("the input mesh"),
      std::string::npos);
  EXPECT_EQ(readAll(scratch / "m.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  // spectrum --specimen S.toml --out S.toml
  const std::string specimen = scratch / "S.toml";
  fs::copy_file(kSource / "scenes/specimens/S1.toml", specimen);
  const std::string specimenText = readAll(specimen);
  EXPECT_NE(errorOf({"spectrum", "--specimen", specimen, "--wavelengths", "550", "--rays", "10",
                     "--out", specimen})
                .find("input"),
            std::string::npos);
  EXPECT_EQ(readAll(specimen), specimenText);
  // image-diff a.exr b.exr --csv a.exr
  const std::string a = scratch / "a.exr", b = scratch / "b.exr";
  std::ofstream(a) << "a";
  std::ofstream(b) << "b";
  EXPECT_NE(errorOf({"image-diff", a, b, "--csv", a}).find("input"), std::string::npos);
  EXPECT_EQ(readAll(a), "a");
  // --plot equal to --out
  const std::string csv = scratch / "s.csv";
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"spectrum", "--wavelengths", "550", "--rays", "10", "--out", csv,
                                 "--plot", csv},
        std::vector<std::string>{"brdf", "--wavelengths", "550", "--rays", "10", "--out", csv,
                                 "--plot", csv},
        std::vector<std::string>{"coefficients", "--specimen", "S1", "--wavelengths", "550",
                                 "--out", csv, "--plot", csv}}) {
    EXPECT_NE(errorOf(args).find("same file"), std::string::npos) << args[0];
    EXPECT_FALSE(fs::exists(csv)) << args[0];
  }
  // fit --specimen S.toml --out S.toml: the fitted specimen over its start
  EXPECT_NE(
      errorOf({"fit", "--specimen", specimen, "--measured",
               (kSource / "tests/data/validation/ncsu_vrhel1994_skin.csv").string() + ":obj117",
               "--out", specimen})
          .find("input"),
      std::string::npos);
  EXPECT_EQ(readAll(specimen), specimenText);
  // figure a/x.toml b/x.toml: two renders into one DIR/x.exr
  fs::create_directories(scratch.path / "a");
  fs::create_directories(scratch.path / "b");
  fs::copy_file(kScene, scratch.path / "a/x.toml");
  fs::copy_file(kScene, scratch.path / "b/x.toml");
  const std::string error = errorOf({"figure", scratch / "a/x.toml", scratch / "b/x.toml", "--out",
                                     scratch / "fig", "--spp", "1"});
  EXPECT_NE(error.find("would both be written"), std::string::npos) << error;
  EXPECT_FALSE(fs::exists(scratch.path / "fig" / "x.exr"));
}

// ---- row 7 ------------------------------------------------------------------------------------

TEST(HostileUse, Row7AnOutputThatCannotBeWrittenFailsAtOnceWithAClearMessage) {
  const Scratch scratch("row7");
  fs::create_directories(scratch.path / "folder");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {scratch / "missing/x.csv", "does not exist"},
      {scratch / "o/", "names a folder"},
      {"", "empty path"},
      {scratch / "folder", "is a folder"},
  };
  for (const auto& [out, why] : cases) {
    const std::string slab = errorOf(slabWith({"--out", out}));
    EXPECT_NE(slab.find(why), std::string::npos) << "'" << out << "': " << slab;
    const std::string render = errorOf({"render", kScene, "--out", out, "--spp", "1"});
    EXPECT_NE(render.find(why), std::string::npos) << "'" << out << "': " << render;
  }
  if (::geteuid() != 0) {  // root writes anywhere
    fs::create_directories(scratch.path / "readonly");
    fs::permissions(scratch.path / "readonly", fs::perms::owner_read | fs::perms::owner_exec);
    const std::string error =
        errorOf({"render", kScene, "--out", scratch / "readonly/x.exr", "--spp", "1"});
    EXPECT_NE(error.find("cannot write in its folder"), std::string::npos) << error;
  }
}

// ---- row 8 ------------------------------------------------------------------------------------

TEST(HostileUse, Row8ResolutionHasTheSceneFilesLimitsAndSaysWhichIsExceeded) {
  EXPECT_EQ(parseResolution("16384x4096"), std::make_pair(16384, 4096));
  EXPECT_EQ(parseResolution("8192x8192"), std::make_pair(8192, 8192));
  for (const std::string text : {"16384x16384", "16385x1", "100000x100000"}) {
    try {
      parseResolution(text);
      ADD_FAILURE() << text << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("limit"), std::string::npos) << e.what();
    }
  }
  for (const std::string text : {"0x5", "-1x5", "5x", "x5", "5x5x5", "1e3x2"})
    EXPECT_THROW(parseResolution(text), std::invalid_argument) << text;
}

TEST(HostileUse, Row8ARenderThatWouldNotFitInMemoryIsRefusedUpFront) {
  const Scratch scratch("row8mem");
  ::setenv("HYLIOS_MEMORY_BUDGET", "100000", 1);  // 100 kB: a 64x64 film needs about 460 kB
  const std::string error = errorOf({"render", kScene, "--out", scratch / "x.exr", "--spp", "1"});
  ::unsetenv("HYLIOS_MEMORY_BUDGET");
  EXPECT_NE(error.find("GiB of memory is available"), std::string::npos) << error;
  EXPECT_FALSE(fs::exists(scratch.path / "x.exr"));
}

// ---- row 10 -----------------------------------------------------------------------------------

TEST(HostileUse, Row10WavelengthsAreWrittenWithEveryDigitTheyHave) {
  const Scratch scratch("row10");
  const std::string out = scratch / "s.csv";
  ASSERT_EQ(errorOf({"spectrum", "--wavelengths", "550.0001,550.0002,1234.5678", "--rays", "20",
                     "--out", out}),
            "");
  std::istringstream csv(readAll(out));
  std::string line;
  std::getline(csv, line);
  std::vector<std::string> first;
  while (std::getline(csv, line)) first.push_back(line.substr(0, line.find(',')));
  EXPECT_EQ(first, (std::vector<std::string>{"550.0001", "550.0002", "1234.5678"}));
  // A 0.0025 nm grid: every row its own wavelength, the last two 2499.9975 and 2500.
  const std::vector<double> grid = parseWavelengthList("2499.99:2500:0.0025");
  ASSERT_EQ(grid.size(), 5u);
  EXPECT_EQ(formatWavelength(grid[3]), "2499.9975");
  EXPECT_EQ(formatWavelength(grid[4]), "2500");
  EXPECT_EQ(formatWavelength(parseWavelengthList("400:700:0.1")[3]), "400.3");
}

// ---- row 11 -----------------------------------------------------------------------------------

TEST(HostileUse, Row11ASpecimenFolderIsCalledAFolder) {
  const Scratch scratch("row11");
  const std::string error = errorOf({"spectrum", "--specimen", scratch.path.string() + "/",
                                     "--wavelengths", "550", "--out", scratch / "s.csv"});
  EXPECT_NE(error.find("is a folder"), std::string::npos) << error;
}

}  // namespace
}  // namespace hylios
