#pragma once
/// @file Helpers of the output writers' tests: a scratch directory per test, and reading back the
/// files written.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace ancfnet::test {

/// An empty directory of its own for the running test.
inline std::filesystem::path MakeTestDirectory() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir =
      std::filesystem::path(::testing::TempDir()) /
      fmt::format("ancfnet_{}_{}", info->test_suite_name(), info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// The whole text of a file ("" when it cannot be read).
inline std::string ReadFile(const std::filesystem::path& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

/// The numbers of the DataArray called `name` in a VTK XML file (a failure when it has none).
inline std::vector<double> ReadDataArray(const std::string& xml, const std::string& name) {
  const std::size_t tag = xml.find("Name=\"" + name + "\"");
  EXPECT_NE(tag, std::string::npos) << name;
  if (tag == std::string::npos) return {};
  const std::size_t begin = xml.find('>', tag) + 1;
  const std::size_t end = xml.find("</DataArray>", begin);
  std::istringstream stream(xml.substr(begin, end - begin));
  std::vector<double> values;
  for (double value; stream >> value;) values.push_back(value);
  return values;
}

}  // namespace ancfnet::test
