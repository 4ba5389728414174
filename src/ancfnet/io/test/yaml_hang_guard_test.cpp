// The inputs on which yaml-cpp 0.7 never returns (found by fuzzing the scene loader) are refused
// with their line and column before it sees them, and nothing valid is refused.

#include "ancfnet/io/yaml_hang_guard.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

#include "ancfnet/common/error.hpp"
#include "ancfnet/io/scene_loader.hpp"

namespace ancfnet {
namespace {

std::string Refusal(const std::string& text) {
  try {
    RefuseYamlThatHangsTheParser(text, "s.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(YamlHangGuard, ADocumentStartingWithACommaIsRefusedAtIt) {
  const std::string why = "invalid YAML: a ',' cannot start a document";
  EXPECT_NE(Refusal(",\n").find("s.yaml:1:1: " + why), std::string::npos);
  EXPECT_NE(Refusal("# comment\n\n  ,# x\nmaterials: {}\n").find("s.yaml:3:3: " + why),
            std::string::npos);
  EXPECT_NE(Refusal("\xEF\xBB\xBF, a\n").find("s.yaml:1:1: " + why), std::string::npos);
  EXPECT_NE(Refusal("%YAML 1.2\n---\n,\n").find("s.yaml:3:1: " + why), std::string::npos);
  EXPECT_NE(Refusal("--- ,\n").find("s.yaml:1:5: " + why), std::string::npos);
  EXPECT_NE(Refusal("a: 1\n...\n,\n").find("s.yaml:3:1: " + why), std::string::npos);
  EXPECT_NE(Refusal("a: 1\n---\n&anchor,\n").find("s.yaml:3:8: " + why), std::string::npos);
  EXPECT_NE(Refusal("!tag ,\n").find("s.yaml:1:6: " + why), std::string::npos);
  EXPECT_NE(Refusal("&a\n,\n").find("s.yaml:2:1: " + why), std::string::npos);
}

TEST(YamlHangGuard, AFlowRootNodeFollowedByACommaIsRefusedAtTheComma) {
  const std::string why = "invalid YAML: a ',' cannot follow a document's root node";
  EXPECT_NE(Refusal("[],").find("s.yaml:1:3: " + why), std::string::npos);
  EXPECT_NE(Refusal("{a: [1, \"]\"]}  # c\n\n  , b\n").find("s.yaml:3:3: " + why),
            std::string::npos);
  EXPECT_NE(Refusal("'it''s', x\n").find("s.yaml:1:8: " + why), std::string::npos);
  EXPECT_NE(Refusal("a: 1\n---\n\"x\\\"\",\n").find("s.yaml:3:6: " + why), std::string::npos);
}

TEST(YamlHangGuard, ACommaAfterAnIndentedBlockRootIsRefusedAtIt) {
  EXPECT_NE(Refusal("# c\n    end: [1, 0, 0]\n\n , width: 0.01}\n")
                .find("s.yaml:4:2: invalid YAML: a ',' cannot follow a document's root node"),
            std::string::npos);
  EXPECT_EQ(Refusal("  a: 1\n  b: |\n    , text\n  c: [1\n    , 2]\n"), "");
}

TEST(YamlHangGuard, CommasInsideADocumentPass) {
  EXPECT_EQ(Refusal("a: [1, 2]\nb: {c: 1, d: 2}\n"), "");
  EXPECT_EQ(Refusal("a: 1\n,\n"), "");  // yaml-cpp refuses it in time
  EXPECT_EQ(Refusal("a: |\n  ,\n---\nb: 2\n"), "");
  EXPECT_EQ(Refusal("- &x 1\n- ,y\n"), "");
  EXPECT_EQ(Refusal(""), "");
  EXPECT_EQ(Refusal("{\"materials\": {}, \"cables\": []}\n"), "");  // a JSON scene
  EXPECT_EQ(Refusal("a: [],\nb: {},\n"), "");
  EXPECT_EQ(Refusal("[1, 2]\n---\nx, y\n"), "");
}

// An input found by fuzzing that none of the rules above foresees: yaml-cpp reads it in a child
// process, which is stopped after the limit of CPU time; on a machine that is not overloaded the
// wall-clock time is about the same.
TEST(YamlHangGuard, AnyInputYamlCppLoopsOnIsRefusedAfterTheTimeLimit) {
  const char* root = std::getenv("ANCFNET_SOURCE_DIR");
  ASSERT_NE(root, nullptr) << "ANCFNET_SOURCE_DIR must name the source tree";
  std::ifstream in(std::string(root) + "/fuzz/regressions/yaml_cpp_hang_12a1acf0.yaml",
                   std::ios::binary);
  ASSERT_TRUE(in);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto start = std::chrono::steady_clock::now();
  EXPECT_NE(Refusal(text).find(
                "s.yaml: invalid YAML: the YAML reader did not finish within 2 s of CPU time"),
            std::string::npos);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 5.0 * kYamlParseSeconds);
}

TEST(YamlHangGuard, TheSceneLoaderRefusesSuchADocumentAtOnce) {
  try {
    ParseScene("# scene\n, materials: {}\n", "scene.yaml");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("scene.yaml:2:1: invalid YAML"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace ancfnet
