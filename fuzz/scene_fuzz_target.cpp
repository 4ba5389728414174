// libFuzzer target for the scene loader: any byte string is parsed as a scene (YAML text, then
// the model through ModelBuilder). A clear refusal (InputError) is the expected answer to bad
// input; anything else that leaves ParseScene — another exception, a crash, a sanitizer report,
// a hang past libFuzzer's -timeout — is a finding. Built with clang's -fsanitize=fuzzer by
// `make fuzz` (scripts/run-fuzzer.sh), and with replay_main.cpp into the `fuzz.regressions` test
// of every build, which replays the seeds and every input that once failed (fuzz/regressions/).

#include <cstddef>
#include <cstdint>
#include <string>

#include "ancfnet/common/error.hpp"
#include "ancfnet/io/scene_loader.hpp"

#ifndef ANCFNET_FUZZ_SCENE_DIRECTORY
#error "ANCFNET_FUZZ_SCENE_DIRECTORY: the directory relative file names in a scene start from"
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    // As `ancfnet check` loads it: with the work limit of a run without --force.
    ancfnet::ParseScene(text, "<fuzz>", ANCFNET_FUZZ_SCENE_DIRECTORY,
                        {.max_unknown_steps = ancfnet::kMaxUnknownSteps});
  } catch (const ancfnet::InputError&) {
  }
  return 0;
}
