// Tests of the CSV spectral table reader: parsing, interpolation, and errors naming file:line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "skin/spectral_table.h"
#include "tests/support/test_folder.h"

namespace hylios::skin {
namespace {

namespace fs = std::filesystem;

class SpectralTableTest : public ::testing::Test {
 protected:
  fs::path dir_;
  void SetUp() override { dir_ = hylios::test::freshTestFolder("hylios_spectral_table_"); }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path file = dir_ / name;
    std::ofstream(file) << text;
    return file;
  }

  /// The message of the SpectralTableError that loading `file` throws ("" if none).
  static std::string loadError(const fs::path& file,
                               DuplicateWavelengths d = DuplicateWavelengths::Reject) {
    try {
      SpectralTable::loadCsv(file, d);
    } catch (const SpectralTableError& e) {
      return e.what();
    }
    return "";
  }
  /// loadError(file), expected to name `file` and `line` ("file:line").
  static std::string errorAt(const fs::path& file, int line) {
    const std::string message = loadError(file);
    EXPECT_NE(message.find(file.string() + ":" + std::to_string(line)), std::string::npos)
        << message;
    return message;
  }
};

TEST_F(SpectralTableTest, ReadsColumnsAndInterpolatesLinearly) {
  const fs::path file = write("t.csv", "wavelength_nm,a,b\n400,1.0,10\n500,3.0,20\n\n600,2.0,40\n");
  const SpectralTable t = SpectralTable::loadCsv(file);
  ASSERT_EQ(t.rowCount(), 3u);
  EXPECT_EQ(t.columnNames(), (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(t.columnIndex("b"), 1u);
  EXPECT_DOUBLE_EQ(t.minWavelengthNm(), 400.0);
  EXPECT_DOUBLE_EQ(t.maxWavelengthNm(), 600.0);
  // Hand values: a(450) = 1 + 0.5·(3 − 1) = 2; b(575) = 20 + 0.75·(40 − 20) = 35; rows exact.
  EXPECT_DOUBLE_EQ(t.interpolate(0, 450.0), 2.0);
  EXPECT_DOUBLE_EQ(t.interpolate(1, 575.0), 35.0);
  EXPECT_DOUBLE_EQ(t.interpolate(0, 400.0), 1.0);
  EXPECT_DOUBLE_EQ(t.interpolate(1, 600.0), 40.0);
}

TEST_F(SpectralTableTest, AcceptsCarriageReturnsAndSpaces) {
  const fs::path file = write("crlf.csv", "wavelength_nm, v\r\n 1 , 2 \r\n3,4\r\n");
  const SpectralTable t = SpectralTable::loadCsv(file);
  EXPECT_DOUBLE_EQ(t.interpolate(t.columnIndex("v"), 2.0), 3.0);
}

TEST_F(SpectralTableTest, RefusesWavelengthsOutsideTheTable) {
  const SpectralTable t = SpectralTable::loadCsv(write("t.csv", "nm,v\n400,1\n500,2\n"));
  EXPECT_THROW(t.interpolate(0, 399.999), SpectralTableError);
  EXPECT_THROW(t.interpolate(0, 500.001), SpectralTableError);
  EXPECT_THROW(t.interpolate(1, 450.0), SpectralTableError);  // no such column
  EXPECT_FALSE(t.covers(399.0));
  EXPECT_TRUE(t.covers(450.0));
}

TEST_F(SpectralTableTest, NonNumericFieldNamesFileAndLine) {
  const std::string message = errorAt(write("bad.csv", "nm,v\n400,1\n500,abc\n"), 3);
  EXPECT_NE(message.find("abc"), std::string::npos) << message;
}

TEST_F(SpectralTableTest, NonFiniteAndEmptyFieldsAreErrors) {
  EXPECT_NE(loadError(write("nan.csv", "nm,v\n400,nan\n")).find(":2"), std::string::npos);
  EXPECT_NE(loadError(write("inf.csv", "nm,v\n400,1\n500,inf\n")).find(":3"), std::string::npos);
  EXPECT_NE(loadError(write("empty.csv", "nm,v\n400,\n")).find(":2"), std::string::npos);
}

TEST_F(SpectralTableTest, DescendingWavelengthNamesFileAndLine) {
  const std::string message = errorAt(write("desc.csv", "nm,v\n400,1\n500,2\n450,3\n"), 4);
  EXPECT_NE(message.find("does not ascend"), std::string::npos) << message;
}

TEST_F(SpectralTableTest, DuplicateWavelengthsAreRejectedOrAveraged) {
  const fs::path file = write("dup.csv", "nm,v,w\n400,1,5\n500,2,6\n500,4,8\n500,6,10\n600,3,7\n");
  errorAt(file, 4);
  const SpectralTable t = SpectralTable::loadCsv(file, DuplicateWavelengths::Average);
  ASSERT_EQ(t.rowCount(), 3u);
  EXPECT_DOUBLE_EQ(t.interpolate(0, 500.0), 4.0);  // (2 + 4 + 6)/3
  EXPECT_DOUBLE_EQ(t.interpolate(1, 500.0), 8.0);  // (6 + 8 + 10)/3
}

TEST_F(SpectralTableTest, NanRowsAreRejectedOrDropped) {
  const fs::path file = write("nanrows.csv", "nm,v,w\n400,1,2\n500,NaN,3\n600,5,6\n");
  errorAt(file, 3);
  const SpectralTable t =
      SpectralTable::loadCsv(file, DuplicateWavelengths::Reject, MissingValues::DropRow);
  ASSERT_EQ(t.rowCount(), 2u);
  EXPECT_DOUBLE_EQ(t.interpolate(0, 500.0), 3.0);  // 1 + 0.5·(5 − 1), across the dropped row
  // Only the "NaN" marker drops a row; other text is still an error.
  const fs::path text = write("text.csv", "nm,v\n400,1\n500,none\n");
  try {
    SpectralTable::loadCsv(text, DuplicateWavelengths::Reject, MissingValues::DropRow);
    FAIL() << "expected an error";
  } catch (const SpectralTableError& e) {
    EXPECT_NE(std::string(e.what()).find(text.string() + ":3"), std::string::npos) << e.what();
  }
}

TEST_F(SpectralTableTest, WrongFieldCountNamesFileAndLine) {
  errorAt(write("short.csv", "nm,v,w\n400,1,2\n500,3\n"), 3);
}

TEST_F(SpectralTableTest, MissingOrEmptyFileNamesTheFile) {
  const fs::path missing = dir_ / "nowhere.csv";
  const std::string message = loadError(missing);
  EXPECT_NE(message.find(missing.string()), std::string::npos) << message;
  EXPECT_NE(message.find("cannot open"), std::string::npos) << message;
  EXPECT_NE(loadError(write("empty.csv", "")).find("empty"), std::string::npos);
  EXPECT_NE(loadError(write("header_only.csv", "nm,v\n")).find("no data rows"), std::string::npos);
  EXPECT_NE(loadError(write("one_column.csv", "nm\n400\n")).find(":1"), std::string::npos);
}

TEST_F(SpectralTableTest, UnknownColumnListsTheColumns) {
  const SpectralTable t = SpectralTable::loadCsv(write("t.csv", "nm,alpha,beta\n1,2,3\n"));
  try {
    t.columnIndex("gamma");
    FAIL() << "expected an error";
  } catch (const SpectralTableError& e) {
    EXPECT_NE(std::string(e.what()).find("alpha, beta"), std::string::npos) << e.what();
  }
}

TEST_F(SpectralTableTest, RowsWithinKeepsAClosedInterval) {
  const SpectralTable t = SpectralTable::loadCsv(write("t.csv", "nm,v\n1,10\n2,20\n3,30\n4,40\n"));
  const SpectralTable mid = t.rowsWithin(2.0, 3.0);
  EXPECT_EQ(mid.rowCount(), 2u);
  EXPECT_DOUBLE_EQ(mid.interpolate(0, 2.5), 25.0);
  EXPECT_THROW(t.rowsWithin(5.0, 6.0), SpectralTableError);
}

TEST_F(SpectralTableTest, ConstructorValidatesSamples) {
  EXPECT_THROW(SpectralTable("x", {"v"}, {1.0, 1.0}, {{1.0, 2.0}}), SpectralTableError);
  EXPECT_THROW(SpectralTable("x", {"v"}, {1.0, 2.0}, {{1.0}}), SpectralTableError);
  EXPECT_THROW(SpectralTable("x", {"v", "w"}, {1.0}, {{1.0}}), SpectralTableError);
  EXPECT_THROW(SpectralTable("x", {"v"}, {}, {{}}), SpectralTableError);
}

TEST_F(SpectralTableTest, ParsesFromAStreamWithTheGivenName) {
  std::istringstream csv("wavelength_nm,v\n400,1\n410,3\n");
  const SpectralTable t = SpectralTable::parseCsv(csv, "inline.csv");
  EXPECT_EQ(t.sourceName(), "inline.csv");
  EXPECT_DOUBLE_EQ(t.interpolate(0, 405.0), 2.0);
  std::istringstream bad("wavelength_nm,v\n400,1\n390,3\n");
  try {
    SpectralTable::parseCsv(bad, "inline.csv");
    FAIL() << "descending wavelengths accepted";
  } catch (const SpectralTableError& e) {
    EXPECT_NE(std::string(e.what()).find("inline.csv:3:"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hylios::skin
