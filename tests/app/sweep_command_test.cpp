// `hylios sweep` in-process (one process, no MPI): the grid and cases-file parsers (values, order,
// clear errors naming the option or file:line:col), the CSV's rows, and --resume, which keeps the
// journal's cases as recorded and computes only the others. The sweep under mpirun and after a real
// abrupt exit: tests/app/mpi_commands_test.sh.
#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/sweep_cases.h"
#include "app/sweep_journal.h"
#include "skin/core/content_hash.h"
#include "tests/support/file_bytes.h"
#include "tests/support/scratch_csv.h"
#include "tests/support/test_folder.h"

namespace hylios {
namespace {

namespace fs = std::filesystem;

const test::CommandRunner runSweep(registerSweepCommand, "sweep");

using test::readBytes;

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) out.push_back(line);
  return out;
}

using test::errorOf;

TEST(SweepCases, RangeIncludesHiOnTheGridWithRoundTrippingValues) {
  // 0.2 + 3 × 0.1 is 0.5000000000000001 in doubles: values are rounded to 12 digits.
  EXPECT_EQ(parseSweepRange("0.2:0.5:0.1", "--vary x", 100),
            (std::vector<double>{0.2, 0.3, 0.4, 0.5}));
  EXPECT_EQ(parseSweepRange("1:10:4", "--vary x", 100), (std::vector<double>{1, 5, 9}));
  EXPECT_EQ(parseSweepRange("3:3:1", "--vary x", 100), (std::vector<double>{3}));
}

TEST(SweepCases, GridVariesTheFirstOptionSlowestAndExpandsShortNames) {
  const SweepCases cases = parseSweepGrid({"melanosome=1:3:2", "blood_percent=0.5:1.5:0.5"}, 100);
  EXPECT_EQ(cases.keys, (std::vector<std::string>{"melanosome_percent", "blood_percent"}));
  ASSERT_EQ(cases.values.size(), 6u);
  EXPECT_EQ(cases.values[0], (std::vector<double>{1, 0.5}));
  EXPECT_EQ(cases.values[1], (std::vector<double>{1, 1}));
  EXPECT_EQ(cases.values[2], (std::vector<double>{1, 1.5}));
  EXPECT_EQ(cases.values[3], (std::vector<double>{3, 0.5}));
  EXPECT_EQ(cases.values[5], (std::vector<double>{3, 1.5}));
}

TEST(SweepCases, GridErrorsSayWhatAndWhere) {
  auto grid = [](std::vector<std::string> vary) {
    return errorOf([&] { parseSweepGrid(vary, 1000); });
  };
  EXPECT_EQ(grid({"melanosome"}).rfind("--vary melanosome: expected NAME=LO:HI:STEP", 0), 0u);
  EXPECT_NE(grid({"freckles=1:2:1"}).find("unknown specimen quantity 'freckles' (known: "),
            std::string::npos);
  EXPECT_EQ(grid({"blood=1:2"}), "--vary blood=1:2: expected LO:HI:STEP, got '1:2'");
  EXPECT_EQ(grid({"blood=1:x:1"}), "--vary blood=1:x:1: HI 'x' is not a finite number");
  EXPECT_EQ(grid({"blood=1:2:0"}), "--vary blood=1:2:0: STEP must be positive");
  EXPECT_EQ(grid({"blood=1:2:nan"}), "--vary blood=1:2:nan: STEP 'nan' is not a finite number");
  EXPECT_EQ(grid({"blood=3:2:1"}), "--vary blood=3:2:1: HI 2 is below LO 3");
  EXPECT_EQ(grid({"blood=1:2:1", "blood_percent=1:3:1"}),
            "--vary blood_percent=1:3:1: 'blood_percent' is varied twice");
  EXPECT_EQ(grid({"blood=0:100:0.05"}),
            "--vary blood=0:100:0.05: more than 1000 values (a sweep of at most that many cases)");
  EXPECT_EQ(grid({"blood=1:40:1", "melanosome=1:40:1"}),
            "the --vary grid has more than 1000 cases");
}

TEST(SweepCases, CasesFileReadsHeaderAndRowsAndNamesErrorsByLineAndColumn) {
  const SweepCases cases = parseSweepCasesText(
      "# my cases\nmelanosome, oxygenation_percent\n\n2, 70\n# skip\n4.5,80\n", "c.csv", 10);
  EXPECT_EQ(cases.keys, (std::vector<std::string>{"melanosome_percent", "oxygenation_percent"}));
  ASSERT_EQ(cases.values.size(), 2u);
  EXPECT_EQ(cases.values[1], (std::vector<double>{4.5, 80}));
  EXPECT_EQ(cases.origins[1], "c.csv:6:1");
  auto file = [](const std::string& text) {
    return errorOf([&] { parseSweepCasesText(text, "c.csv", 10); });
  };
  EXPECT_EQ(file("blood\n1\n2,3\n"), "c.csv:3:1: 2 values, the header names 1 quantities");
  EXPECT_EQ(file("blood,melanosome\n1, two\n"), "c.csv:2:4: 'two' is not a finite number");
  EXPECT_NE(file("blood,hair\n1,2\n").find("c.csv:1:7: unknown specimen quantity 'hair'"),
            std::string::npos);
  EXPECT_EQ(file("# nothing\n"), "c.csv: no header line naming the quantities");
  EXPECT_EQ(file("blood\n"), "c.csv: no cases after the header");
  EXPECT_EQ(file("blood\n1\n2\n3\n4\n5\n6\n7\n8\n9\n10\n11\n"), "c.csv:12:1: more than 10 cases");
}

class SweepCommand : public ::testing::Test {
 protected:
  // A folder of each test's own: CTest runs the tests of this fixture in parallel.
  void SetUp() override { dir_ = test::freshTestFolder("sweep_command_test_"); }
  std::vector<std::string> args(const fs::path& out) const {
    return {"--specimen", "S1",      "--vary", "melanosome=2:6:2", "--wavelengths",
            "450,650",    "--angle", "0,30",   "--rays",           "2000",
            "--seed",     "4",       "--out",  out.string()};
  }
  fs::path dir_;
};

TEST_F(SweepCommand, WritesOneRowPerCaseAngleAndWavelengthInCaseOrder) {
  const fs::path out = dir_ / "grid.csv";
  runSweep(args(out));
  const auto rows = lines(readBytes(out));
  ASSERT_EQ(rows.size(), 1u + 3 * 2 * 2);
  EXPECT_EQ(rows[0],
            "case,melanosome_percent,angle_deg,wavelength_nm,reflectance,reflectance_stderr,"
            "surface_reflectance,subsurface_reflectance,transmittance,absorptance,"
            "absorptance_stderr");
  EXPECT_EQ(rows[1].rfind("0,2,0,450,", 0), 0u);
  EXPECT_EQ(rows[2].rfind("0,2,0,650,", 0), 0u);
  EXPECT_EQ(rows[3].rfind("0,2,30,450,", 0), 0u);
  EXPECT_EQ(rows[12].rfind("2,6,30,650,", 0), 0u);
  EXPECT_FALSE(fs::exists(sweepJournalPath(out)));
}

TEST_F(SweepCommand, ResumeKeepsTheJournalsCasesAndComputesTheRest) {
  const fs::path whole = dir_ / "whole.csv";
  runSweep(args(whole));
  const std::string wholeCsv = readBytes(whole);
  // An interrupted run (the test hook stops it after 2 journaled cases) leaves no output and a
  // journal of cases 0 and 1.
  const fs::path out = dir_ / "resumed.csv";
  ::setenv("HYLIOS_TEST_SWEEP_EXIT", "0:2:throw", 1);
  EXPECT_EQ(errorOf([&] { runSweep(args(out)); }), "HYLIOS_TEST_SWEEP_EXIT: stopped after 2 cases");
  ::unsetenv("HYLIOS_TEST_SWEEP_EXIT");
  EXPECT_FALSE(fs::exists(out));
  const fs::path journal = sweepJournalPath(out);
  std::string text = readBytes(journal);
  ASSERT_EQ(lines(text).size(), 1u + 2 * (1 + 4 + 1));
  // Without --resume the journal is refused and left as it is.
  EXPECT_NE(errorOf([&] { runSweep(args(out)); }).find("holds an interrupted sweep"),
            std::string::npos);
  EXPECT_EQ(readBytes(journal), text);
  // Case 1's first reflectance is altered (and its record's hash with it, through SweepJournal),
  // and a torn record of case 2 is appended, as a kill while writing would leave it.
  EXPECT_NE(errorOf([&] { readSweepJournal(journal, 0, 3); })
                .find(  // another definition
                    "is the journal of another sweep"),
            std::string::npos);
  const std::string header = lines(text)[0] + "\n";
  std::string case0, case1;
  const auto all = lines(text);
  for (std::size_t r = 2; r <= 5; ++r) case0 += all[r] + "\n";
  for (std::size_t r = 8; r <= 11; ++r) case1 += all[r] + "\n";
  ASSERT_EQ(case1.rfind("1,4,0,450,", 0), 0u);
  const std::string altered = "1,4,0,450,0.123" + case1.substr(case1.find(',', 10));
  {
    std::ofstream rewrite(journal, std::ios::binary | std::ios::trunc);
    rewrite << header;
  }
  {
    // Records as the command appends them (the definition is the header's).
    std::map<std::size_t, std::string> records = {{0, case0}, {1, altered}};
    std::string body;
    for (const auto& [index, rows] : records) {
      body += "case " + std::to_string(index) + "\n" + rows + "end " + std::to_string(index) + " " +
              skin::hex64(skin::fnv1a64(rows.data(), rows.size())) + "\n";
    }
    std::ofstream append(journal, std::ios::binary | std::ios::app);
    append << body << "case 2\n2,6,0,450,0.3";  // torn
  }
  runSweep([&] {
    auto a = args(out);
    a.push_back("--resume");
    return a;
  }());
  const std::string resumed = readBytes(out);
  EXPECT_FALSE(fs::exists(journal));
  // Everything equals the uninterrupted sweep but the altered value, kept from the journal.
  std::string expected = wholeCsv;
  const auto at = expected.find(case1);
  ASSERT_NE(at, std::string::npos);
  expected.replace(at, case1.size(), altered);
  EXPECT_EQ(resumed, expected);
}

TEST_F(SweepCommand, RefusesBothOrNeitherCaseSourceAndBadValuesBeforeAnyWork) {
  const fs::path out = dir_ / "bad.csv";
  EXPECT_EQ(errorOf([&] {
              runSweep({"--out", out.string()});
            }),
            "give the cases as --vary NAME=LO:HI:STEP (repeatable, a grid) or as --cases FILE, "
            "not both");
  // 150 % melanosomes: the override's range check names the case.
  const std::string message = errorOf([&] {
    runSweep({"--vary", "melanosome=50:150:50", "--out", out.string()});
  });
  EXPECT_NE(message.find("melanosome_percent = 150"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(sweepJournalPath(out)));
}

}  // namespace
}  // namespace hylios
