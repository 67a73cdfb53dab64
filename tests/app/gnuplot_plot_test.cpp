#include "app/gnuplot_plot.h"

#include <gtest/gtest.h>

#include <fstream>

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
  EXPECT_THROW(hylios::plotPanels(png, "t", {{"p", "x", "y", true, {series}}}), std::invalid_argument);
  EXPECT_FALSE(fs::exists(png));
}
