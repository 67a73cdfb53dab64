#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>

#include "app/gnuplot_plot.h"

namespace fs = std::filesystem;

TEST(GnuplotPlot, WritesAPngWithErrorBand) {
  const fs::path png = fs::temp_directory_path() / "hylios_plot_test.png";
  fs::remove(png);
  hylios::PlotSeries series{"curve", {1, 2, 3}, {0.1, 0.2, 0.15}, {0.01, 0.02, 0.01}, ""};
  hylios::plotPanels(png, "test", {{"panel", "x", "y", false, {series}}});
  ASSERT_TRUE(fs::exists(png));
  std::ifstream in(png, std::ios::binary);
  char magic[8] = {};
  in.read(magic, 8);
  EXPECT_EQ(std::string(magic + 1, 3), "PNG");
  EXPECT_GT(fs::file_size(png), 1000u);
  fs::remove(png);
}

TEST(GnuplotPlot, UnequalColumnsAreAnErrorAndLeaveNoFile) {
  const fs::path png = fs::temp_directory_path() / "hylios_plot_bad.png";
  fs::remove(png);
  hylios::PlotSeries series{"bad", {1, 2, 3}, {0.1, 0.2}, {}, ""};
  EXPECT_THROW(hylios::plotPanels(png, "t", {{"p", "x", "y", true, {series}}}),
               std::invalid_argument);
  EXPECT_FALSE(fs::exists(png));
}

// Issue 13 row 11: a plot that cannot be written says why, not "is gnuplot-nox installed?";
// a missing gnuplot says that it is missing.
TEST(GnuplotPlot, AWriteFailureSaysWhyAndAMissingGnuplotSaysSo) {
  hylios::PlotSeries series{"curve", {1, 2, 3}, {0.1, 0.2, 0.15}, {}, ""};
  const fs::path unwritable = fs::temp_directory_path() / "hylios_no_such_folder" / "plot.png";
  try {
    hylios::plotPanels(unwritable, "t", {{"p", "x", "y", false, {series}}});
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).find("installed"), std::string::npos) << e.what();
  }
  const char* path = std::getenv("PATH");
  const std::string saved = path ? path : "";
  ::setenv("PATH", "/hylios-no-such-dir", 1);
  const fs::path png = fs::temp_directory_path() / "hylios_plot_nognuplot.png";
  std::string message;
  try {
    hylios::plotPanels(png, "t", {{"p", "x", "y", false, {series}}});
  } catch (const std::runtime_error& e) {
    message = e.what();
  }
  ::setenv("PATH", saved.c_str(), 1);
  EXPECT_NE(message.find("gnuplot is not installed"), std::string::npos) << message;
}
