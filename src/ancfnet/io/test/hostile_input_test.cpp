// Scene input a careless or hostile user gives (issue "Reliability gates"), refused at once with
// file, line and key: names that would break probes.csv or summary.json, two things of a kind
// with one name, a second YAML document, a step count no run could finish, and files that are
// not scenes (a device, a file larger than 64 MiB). docs/reliability.md lists each class.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "ancfnet/common/error.hpp"
#include "ancfnet/io/scene_loader.hpp"
#include "cantilever_scene.hpp"

namespace ancfnet {
namespace {

using test::Cantilever;
using test::ErrorOf;

constexpr const char* kTipProbe = "  - {name: tip, quantity: position, at: beam.end}\n";

// The cantilever with its probe line replaced by `probes` (each line "  - {…}").
std::string WithProbes(const std::string& probes) { return Cantilever(kTipProbe, probes); }

// The cantilever with a square net of steel bars whose other keys are `fields` (line 18 holds
// "  - {name: net, type: square, side: 1.0, " and then `fields`).
std::string WithNet(const std::string& fields) {
  return Cantilever("probes:\n", "nets:\n  - {name: net, type: square, side: 1.0, " + fields +
                                      ", material: steel,\n     section: bar}\nprobes:\n");
}

TEST(HostileInput, NamesThatWouldBreakTheCsvOrTheJsonAreRefused) {
  const std::string why =
      "a name may not hold commas, double quotes, line breaks or other control characters (it "
      "heads CSV columns and keys summary.json) (key 'name')";
  EXPECT_EQ(ErrorOf(WithProbes("  - {name: \"tip,x\", quantity: position, at: beam.end}\n")),
            "scene.yaml:18:12: " + why);
  EXPECT_EQ(ErrorOf(WithProbes("  - {name: \"tip\\nx\", quantity: position, at: beam.end}\n")),
            "scene.yaml:18:12: " + why);
  EXPECT_EQ(ErrorOf(WithProbes("  - {name: 'say \"hi\"', quantity: position, at: beam.end}\n")),
            "scene.yaml:18:12: " + why);
  EXPECT_EQ(ErrorOf(WithProbes("  - {name: \" tip\", quantity: position, at: beam.end}\n")),
            "scene.yaml:18:12: a name may not start or end with a blank (key 'name')");
  EXPECT_EQ(ErrorOf(WithProbes("  - {name: " + std::string(129, 'a') +
                               ", quantity: position, at: beam.end}\n")),
            "scene.yaml:18:12: a name has at most 128 characters (got 129) (key 'name')");
  EXPECT_EQ(ErrorOf(WithProbes("  - {name: tip.x-1_a:b, quantity: position, at: beam.end}\n")), "");
}

TEST(HostileInput, TwoThingsOfAKindWithOneNameAreRefused) {
  EXPECT_EQ(ErrorOf(WithProbes(std::string(kTipProbe) +
                               "  - {name: tip, quantity: velocity, at: beam.end}\n")),
            "scene.yaml:19:12: two probes are named 'tip' (the first at scene.yaml:18:12) (key "
            "'name')");
  const std::string link =
      "  - {name: link, from: beam.start, to: beam.end, law: {type: linear, stiffness: 1}}\n";
  EXPECT_EQ(ErrorOf(Cantilever("probes:\n", "spring_dampers:\n" + link + link + "probes:\n")),
            "scene.yaml:19:12: two spring-dampers are named 'link' (the first at "
            "scene.yaml:18:12) (key 'name')");
  const std::string contact = R"(contact:
  law: {type: hertz, stiffness: 1.0e6}
  targets:
    - {name: ball, type: sphere, center: [0, 0, -1], radius: 0.1}
    - {name: ball, type: sphere, center: [0, 0, 1], radius: 0.1}
probes:
)";
  EXPECT_EQ(ErrorOf(Cantilever("probes:\n", contact)),
            "scene.yaml:21:14: two contact targets are named 'ball' (the first at "
            "scene.yaml:20:14) (key 'name')");
  const std::string unnamed = R"(contact:
  law: {type: hertz, stiffness: 1.0e6}
  targets:
    - {type: sphere, center: [0, 0, -1], radius: 0.1}
    - {type: sphere, center: [0, 0, 1], radius: 0.1}
probes:
)";
  EXPECT_EQ(ErrorOf(Cantilever("probes:\n", unnamed)),
            "scene.yaml:21:7: two contact targets are named 'target' (the first at "
            "scene.yaml:20:7) (key 'targets[1]')");
}

TEST(HostileInput, ASecondYamlDocumentIsRefused) {
  EXPECT_EQ(ErrorOf(Cantilever() + "---\ngravity: [0, 0, -9.81]\n"),
            "scene.yaml:23: a second YAML document (after '---'): a scene is one document, and "
            "the rest would be ignored");
}

TEST(HostileInput, AStepCountNoRunCouldFinishIsRefused) {
  EXPECT_EQ(ErrorOf(Cantilever("  type: static\n", "  type: dynamic\n  time_step: 1.0e-300\n")),
            "scene.yaml:21:14: time_step 1e-300 s to end_time 1 s is 1e+300 steps; at most 1e+09 "
            "are accepted (key 'time_step')");
  EXPECT_EQ(ErrorOf(Cantilever("  type: static\n", "  type: dynamic\n  time_step: 1.0e-9\n")), "");
}

TEST(HostileInput, AnEstimatedWorkBeyondTheLimitAsksForForce) {
  // 10⁹ steps of the cantilever's 102 coordinates; the CLI's limit is kMaxUnknownSteps.
  const std::string scene =
      Cantilever("  type: static\n", "  type: dynamic\n  time_step: 1.0e-7\n  end_time: 100\n");
  const auto error_with_limit = [&](double limit) -> std::string {
    try {
      ParseScene(scene, "scene.yaml", {}, {.max_unknown_steps = limit});
    } catch (const InputError& error) {
      return error.what();
    }
    return "";
  };
  EXPECT_EQ(error_with_limit(1e11),
            "scene.yaml:21:14: 1e+09 steps (end_time 100 s / time_step 1e-07 s) of 102 unknowns "
            "are 1.02e+11 unknown-steps, above the limit of 1e+11 (10¹² take months on one core); "
            "check time_step and end_time, or run it anyway with --force (key 'time_step')");
  EXPECT_EQ(error_with_limit(1.1e11), "");
  EXPECT_EQ(error_with_limit(0.0), "");  // --force
  EXPECT_EQ(ErrorOf(scene), "");         // no limit unless asked
  EXPECT_EQ(kMaxUnknownSteps, 1e12);
}

TEST(HostileInput, FilesThatAreNotScenesAreRefusedBeforeReading) {
  auto error_of_file = [](const std::filesystem::path& file) -> std::string {
    try {
      LoadScene(file);
    } catch (const InputError& error) {
      return error.what();
    }
    return "";
  };
  EXPECT_EQ(error_of_file("/dev/zero"), "/dev/zero: not a regular file (a scene is read from a file)");
  // A sparse file of 64 MiB + 1 byte: refused by its size, without being read.
  const std::filesystem::path big = std::filesystem::temp_directory_path() / "ancfnet_big_scene.yaml";
  std::ofstream(big).put('#');
  std::filesystem::resize_file(big, (std::uintmax_t{64} << 20) + 1);
  EXPECT_EQ(error_of_file(big),
            big.string() + ": 67108865 bytes; a scene file may hold at most 64 MiB");
  std::filesystem::remove(big);
}

TEST(HostileInput, ImplausibleValuesAreRefusedWithTheReason) {
  const std::string contact = R"(contact:
  law: {type: hertz, stiffness: 1.0e6, exponent: 100}
  targets:
    - {name: ball, type: sphere, center: [0, 0, -1], radius: 0.1}
probes:
)";
  EXPECT_EQ(ErrorOf(Cantilever("probes:\n", contact)),
            "scene.yaml:18:50: expected a number in [1, 3], got '100' (key 'exponent')");
  EXPECT_EQ(ErrorOf(WithNet("mesh_size: 2.0, center: [0, 0, 1]")),
            "scene.yaml:18:53: a mesh of 2 m does not fit in a net of side 1 m (key 'mesh_size')");
  // A section thicker than the cable is long (a 1000 km thread on a 1 m cable); elements
  // shorter than it are a refined mesh, not an error.
  EXPECT_EQ(ErrorOf(Cantilever("bar: {shape: rectangle, width: 0.01, height: 0.01}",
                               "bar: {shape: circle, diameter: 1.0e6}")),
            "scene.yaml:12:14: a section 1e+06 m thick (the diameter of its area) is thicker than "
            "cable 'beam' is long (1 m); a cable must be slender: check the unit of the section "
            "(key 'section')");
  EXPECT_EQ(ErrorOf(Cantilever("elements: 16", "elements: 1000")), "");
  EXPECT_EQ(ErrorOf(WithNet("meshes: 100, center: [0, 0, 1]")),
            "scene.yaml:19:15: a section 0.0113 m thick (the diameter of its area) is thicker than "
            "the shortest thread of net 'net' is long (0.01 m); a cable must be slender: check "
            "the unit of the section (key 'section')");
  EXPECT_EQ(ErrorOf(WithNet("meshes: 80, center: [0, 0, 1]")), "");
  // A contact law so stiff that a contact lasts less than 1/1000 of a step.
  const auto with_stiffness = [](const std::string& stiffness) {
    return test::Replace(
        Cantilever("probes:\n", "contact:\n  law: {type: hertz, stiffness: " + stiffness +
                                     "}\n  targets:\n    - {name: ball, type: sphere, center: "
                                     "[0, 0, -1], radius: 0.1}\nprobes:\n"),
        "  type: static\n", "  type: dynamic\n  time_step: 1.0e-3\n");
  };
  const std::string stiff = ErrorOf(with_stiffness("1.0e30"));
  EXPECT_EQ(stiff.rfind("scene.yaml:18:33: a contact of the lightest contact point (0.00696 kg) "
                        "would last 2π √(m/k) = 2.86e-15 s, less than 1/1000 of the time step "
                        "0.001 s: no step could resolve it; check the stiffness and its unit "
                        "(N/m^1.5) (key 'stiffness')",
                        0),
            0u)
      << stiff;
  EXPECT_EQ(ErrorOf(with_stiffness("1.0e9")), "");
  // Axes that are not orthonormal: the message names the net, not its side.
  EXPECT_EQ(ErrorOf(WithNet("meshes: 2, axis_u: [1, 1, 0]")),
            "scene.yaml:18:5: net axes u = [1, 1, 0] and v = [0, 1, 0] must be unit vectors "
            "(key 'nets[0]')");
}

TEST(HostileInput, ANetTooLargeForTheMemoryIsRefusedBeforeItIsBuilt) {
  const std::string error = ErrorOf(WithNet("meshes: 10000, center: [0, 0, 1]"));
  EXPECT_EQ(error.rfind("scene.yaml:18:50: a net of 10000 × 10000 meshes has 2e+08 threads and "
                        "would need at least 4.4e+03 GB; this machine has ",
                        0),
            0u)
      << error;
}

}  // namespace
}  // namespace ancfnet
