#pragma once
// The scene text the io tests edit: the cantilever of examples/cantilever_static.yaml, and how to
// read the error a scene gives.

#include <gtest/gtest.h>

#include <string>

#include "ancfnet/common/error.hpp"
#include "ancfnet/io/scene_loader.hpp"

namespace ancfnet {
namespace test {

// The cantilever of examples/cantilever_static.yaml, without comments, so that the positions in
// the expected messages of the tests can be read off it (line 1 is "gravity").
inline constexpr const char* kCantilever = R"(gravity: [0, 0, 0]
materials:
  steel: {youngs_modulus: 2.0e11, density: 7800}
sections:
  bar: {shape: rectangle, width: 0.01, height: 0.01}
cables:
  - name: beam
    start: [0, 0, 0]
    end: [1, 0, 0]
    elements: 16
    material: steel
    section: bar
constraints:
  - {type: clamp, at: beam.start}
loads:
  - {type: point_force, at: beam.end, force: [0, 0, -333.333]}
probes:
  - {name: tip, quantity: position, at: beam.end}
analysis:
  type: static
  load_steps: 10
)";

// `text` with its first occurrence of `from` replaced by `to` (which must be there).
inline std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "'" << from << "' is not in the scene";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// The cantilever with one edit.
inline std::string Cantilever(const std::string& from = "", const std::string& to = "") {
  return from.empty() ? std::string(kCantilever) : Replace(kCantilever, from, to);
}

// The message of the InputError that parsing `yaml` as "scene.yaml" throws; "" when none.
inline std::string ErrorOf(const std::string& yaml) {
  try {
    ParseScene(yaml, "scene.yaml");
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

}  // namespace test
}  // namespace ancfnet
