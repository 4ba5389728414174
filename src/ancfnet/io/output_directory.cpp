#include "ancfnet/io/output_directory.hpp"

#include <fmt/format.h>

#include <system_error>

#include "ancfnet/common/error.hpp"

namespace ancfnet {

void CreateOutputDirectory(const std::filesystem::path& dir) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error)
    throw InputError(
        fmt::format("cannot create output directory '{}': {}", dir.string(), error.message()));
}

}  // namespace ancfnet
