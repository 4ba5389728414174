#pragma once
// Shared helpers of the mesh tests: the repository's tests/data folder.

#include <cstdlib>
#include <filesystem>

namespace ancfnet {
namespace test {

// tests/data of the repository (CTest sets ANCFNET_SOURCE_DIR; by hand, run from the root).
inline std::filesystem::path MeshDataDir() {
  const char* dir = std::getenv("ANCFNET_SOURCE_DIR");
  const std::filesystem::path root =
      dir != nullptr ? std::filesystem::path(dir) : std::filesystem::current_path();
  return root / "tests" / "data";
}

}  // namespace test
}  // namespace ancfnet
