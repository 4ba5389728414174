// The checkpoint file: its payload read back whole; a file of another scene, one cut short at any
// byte, one with a byte changed, one that is no checkpoint, a directory or a missing file are
// refused with InputError naming the file and what is wrong, never read past their end.

#include "ancfnet/io/checkpoint_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "ancfnet/common/error.hpp"
#include "ancfnet/io/scene_loader.hpp"
#include "output_test_files.hpp"

namespace ancfnet {
namespace {

constexpr const char* kScene = R"(
point_masses:
  - {name: m, mass: 1.0, position: [0, 0, 0]}
analysis: {type: dynamic, time_step: 0.01, end_time: 0.1}
)";

std::vector<std::byte> MakePayload() {
  std::vector<std::byte> payload;
  for (int i = 0; i < 1000; ++i) payload.push_back(static_cast<std::byte>(i * 37 % 251));
  return payload;
}

std::string ReadBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void WriteBytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

// The message of the InputError that reading `path` as a checkpoint of `scene` throws.
std::string Refusal(const std::filesystem::path& path, const Scene& scene) {
  try {
    ReadCheckpointFile(path, scene);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(CheckpointFile, ThePayloadReadsBackWhole) {
  const std::filesystem::path dir = test::MakeTestDirectory();
  const Scene scene = ParseScene(kScene, "a.yaml");
  WriteCheckpointFile(dir / "checkpoint.bin", scene, MakePayload());
  EXPECT_EQ(ReadCheckpointFile(dir / "checkpoint.bin", scene), MakePayload());
  EXPECT_FALSE(std::filesystem::exists(dir / "checkpoint.bin.tmp"));
  // Written again: replaced, not appended to.
  WriteCheckpointFile(dir / "checkpoint.bin", scene, {});
  EXPECT_TRUE(ReadCheckpointFile(dir / "checkpoint.bin", scene).empty());
}

TEST(CheckpointFile, ACheckpointOfAnotherSceneIsRefusedNamingBoth) {
  const std::filesystem::path dir = test::MakeTestDirectory();
  WriteCheckpointFile(dir / "checkpoint.bin", ParseScene(kScene, "a.yaml"), MakePayload());
  const Scene other = ParseScene(std::string(kScene) + "# another text\n", "b.yaml");
  const std::string message = Refusal(dir / "checkpoint.bin", other);
  EXPECT_NE(message.find("checkpoint.bin"), std::string::npos) << message;
  EXPECT_NE(message.find("a.yaml"), std::string::npos) << message;
  EXPECT_NE(message.find("b.yaml"), std::string::npos) << message;
}

TEST(CheckpointFile, EveryTruncationIsRefused) {
  const std::filesystem::path dir = test::MakeTestDirectory();
  const Scene scene = ParseScene(kScene, "a.yaml");
  WriteCheckpointFile(dir / "full.bin", scene, MakePayload());
  const std::string bytes = ReadBytes(dir / "full.bin");
  for (std::size_t size = 0; size < bytes.size(); ++size) {
    WriteBytes(dir / "cut.bin", bytes.substr(0, size));
    const std::string message = Refusal(dir / "cut.bin", scene);
    EXPECT_NE(message.find("cut.bin: "), std::string::npos) << size << ": " << message;
    if (size >= 8)
      EXPECT_NE(message.find("truncated"), std::string::npos) << size << ": " << message;
  }
}

TEST(CheckpointFile, AChangedByteIsRefused) {
  const std::filesystem::path dir = test::MakeTestDirectory();
  const Scene scene = ParseScene(kScene, "a.yaml");
  WriteCheckpointFile(dir / "checkpoint.bin", scene, MakePayload());
  std::string bytes = ReadBytes(dir / "checkpoint.bin");
  bytes[bytes.size() - 10] ^= 0x40;
  WriteBytes(dir / "checkpoint.bin", bytes);
  EXPECT_NE(Refusal(dir / "checkpoint.bin", scene).find("checksum"), std::string::npos);
  WriteBytes(dir / "checkpoint.bin", ReadBytes(dir / "checkpoint.bin") + "x");
  EXPECT_NE(Refusal(dir / "checkpoint.bin", scene).find("damaged"), std::string::npos);
}

TEST(CheckpointFile, WhatIsNoCheckpointIsRefused) {
  const std::filesystem::path dir = test::MakeTestDirectory();
  const Scene scene = ParseScene(kScene, "a.yaml");
  WriteBytes(dir / "scene.yaml", kScene);
  EXPECT_NE(Refusal(dir / "scene.yaml", scene).find("not an ancfnet checkpoint"),
            std::string::npos);
  EXPECT_NE(Refusal(dir / "missing.bin", scene).find("no such checkpoint"), std::string::npos);
  EXPECT_NE(Refusal(dir, scene).find("not a regular file"), std::string::npos);
  WriteCheckpointFile(dir / "checkpoint.bin", scene, MakePayload());
  std::string bytes = ReadBytes(dir / "checkpoint.bin");
  bytes[8] = 99;  // the version
  WriteBytes(dir / "checkpoint.bin", bytes);
  EXPECT_NE(Refusal(dir / "checkpoint.bin", scene).find("version 99"), std::string::npos);
}

}  // namespace
}  // namespace ancfnet
