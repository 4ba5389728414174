// ReadProbeCsv: named columns over a time window, and one clear message for each kind of bad file.

#include "ancfnet/io/probe_csv_reader.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

// `text` written to a file of the running test's own.
std::filesystem::path WriteFile(const std::string& name, const std::string& text) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir =
      std::filesystem::path(::testing::TempDir()) /
      fmt::format("ancfnet_{}_{}", info->test_suite_name(), info->name());
  std::filesystem::create_directories(dir);
  const std::filesystem::path path = dir / name;
  std::ofstream(path) << text;
  return path;
}

// The message of the InputError that ReadProbeCsv throws (a test failure if it throws none).
std::string ErrorOf(const std::filesystem::path& path, const std::vector<std::string>& columns,
                    const ProbeCsvWindow& window = {}) {
  try {
    ReadProbeCsv(path, columns, window);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError for " << path;
  return {};
}

const char* const kProbes =
    "time,tip.x,tip.y,tip.z,e.kinetic\n"
    "0,1,0,-0.5,0\n"
    "0.1,1.25,0.001,-0.25,3.5\n"
    "0.2,1.5,0.002,0.125,1e-3\n"
    "0.30000000000000004,1.75,0.003,2.2250738585072014e-308,7\n";

TEST(ProbeCsvReader, ReadsNamedColumnsInTheOrderAsked) {
  const auto path = WriteFile("probes.csv", kProbes);
  const ProbeSeries s = ReadProbeCsv(path, {"tip.z", "tip.x"});
  EXPECT_EQ(s.columns, (std::vector<std::string>{"tip.z", "tip.x"}));
  ASSERT_EQ(s.time.size(), 4);
  ASSERT_EQ(s.values.rows(), 4);
  ASSERT_EQ(s.values.cols(), 2);
  EXPECT_EQ(s.time(3), 0.30000000000000004);  // shortest round-trip text reads back exactly
  EXPECT_EQ(s.values(1, 0), -0.25);
  EXPECT_EQ(s.values(1, 1), 1.25);
  EXPECT_EQ(s.values(3, 0), 2.2250738585072014e-308);
  EXPECT_EQ(ReadProbeCsv(path, {}).columns.size(), 4u);  // every column but time
}

TEST(ProbeCsvReader, TimeWindowKeepsTheRowsInside) {
  const auto path = WriteFile("probes.csv", kProbes);
  const ProbeSeries s = ReadProbeCsv(path, {"e.kinetic"}, {.from = 0.05, .to = 0.2});
  ASSERT_EQ(s.time.size(), 2);
  EXPECT_EQ(s.time(0), 0.1);
  EXPECT_EQ(s.time(1), 0.2);  // the ends are included
  EXPECT_EQ(s.values(1, 0), 1e-3);
  const std::string message = ErrorOf(path, {"tip.z"}, {.from = 5.0});
  EXPECT_NE(message.find("no row"), std::string::npos) << message;
  EXPECT_NE(message.find("spans 0 s to 0.30000000000000004 s"), std::string::npos) << message;
  EXPECT_NE(ErrorOf(path, {"tip.z"}, {.from = 0.2, .to = 0.1}).find("empty"), std::string::npos);
}

TEST(ProbeCsvReader, SpacesAndCrlfAreAccepted) {
  const auto path = WriteFile("probes.csv", "time, a.x ,b.y\r\n0, 1 ,+2\r\n1,3,4\r\n\r\n");
  const ProbeSeries s = ReadProbeCsv(path, {"a.x", "b.y"});
  ASSERT_EQ(s.time.size(), 2);
  EXPECT_EQ(s.values(0, 1), 2.0);
  EXPECT_EQ(s.values(1, 0), 3.0);
}

TEST(ProbeCsvReader, MissingColumnNamesTheFileAndTheColumns) {
  const auto path = WriteFile("probes.csv", kProbes);
  const std::string typo = ErrorOf(path, {"tip.x", "tip.q"});
  EXPECT_NE(typo.find("probes.csv: no column 'tip.q'"), std::string::npos) << typo;
  EXPECT_NE(typo.find("did you mean"), std::string::npos) << typo;
  EXPECT_NE(typo.find("columns: tip.x, tip.y, tip.z, e.kinetic"), std::string::npos) << typo;
  const std::string far = ErrorOf(path, {"mouth.area"});
  EXPECT_EQ(far.find("did you mean"), std::string::npos) << far;
  EXPECT_NE(far.find("columns: tip.x"), std::string::npos) << far;
  // "time" is not a signal.
  EXPECT_NE(ErrorOf(path, {"time"}).find("no column 'time'"), std::string::npos);
}

TEST(ProbeCsvReader, BadFilesAreRefusedWithTheLine) {
  const std::filesystem::path missing = WriteFile("x.csv", "").parent_path() / "absent.csv";
  EXPECT_NE(ErrorOf(missing, {"a"}).find("cannot open"), std::string::npos);
  EXPECT_NE(ErrorOf(WriteFile("empty.csv", ""), {"a"}).find("empty file"), std::string::npos);
  EXPECT_NE(ErrorOf(WriteFile("header.csv", "t,a\n0,1\n"), {"a"}).find("expected 'time'"),
            std::string::npos);
  EXPECT_NE(ErrorOf(WriteFile("rows.csv", "time,a\n"), {"a"}).find("no data row"),
            std::string::npos);
  const std::string fields = ErrorOf(WriteFile("fields.csv", "time,a,b\n0,1,2\n1,2\n"), {"a"});
  EXPECT_NE(fields.find("fields.csv:3: 2 fields, the header has 3"), std::string::npos) << fields;
  const std::string text = ErrorOf(WriteFile("text.csv", "time,a\n0,1\n1,abc\n"), {"a"});
  EXPECT_NE(text.find("text.csv:3: 'abc' in column 'a' is not a finite number"), std::string::npos)
      << text;
  EXPECT_NE(ErrorOf(WriteFile("nan.csv", "time,a\n0,nan\n"), {"a"}).find("nan.csv:2:"),
            std::string::npos);
  const std::string order = ErrorOf(WriteFile("order.csv", "time,a\n0,1\n1,2\n1,3\n"), {"a"});
  EXPECT_NE(order.find("order.csv:4: time 1 s does not increase"), std::string::npos) << order;
}

}  // namespace
}  // namespace ancfnet
