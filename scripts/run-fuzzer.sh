#!/usr/bin/env bash
# Fuzzes the scene loader (fuzz/scene_fuzz_target.cpp) with libFuzzer for FUZZ_SECONDS seconds
# (default 600), seeded with every example, benchmark and test scene and with fuzz/regressions/,
# and a dictionary of every key those scenes use. A unit slower than 10 s is a hang, one that
# needs more than 4 GiB a memory finding; leaks are reported (AddressSanitizer). Findings are
# written to BUILD/artifacts/; the corpus grows in BUILD/corpus/.
# Usage: scripts/run-fuzzer.sh BUILD   (BUILD: the `fuzz` preset's build directory)
set -euo pipefail

build="${1:?usage: run-fuzzer.sh BUILD}"
root="$(cd "$(dirname "$0")/.." && pwd)"
seconds="${FUZZ_SECONDS:-600}"
fuzzer="$build/fuzz/ancfnet_scene_fuzzer"
[[ -x "$fuzzer" ]] || { echo "run-fuzzer.sh: $fuzzer not built (make fuzz)" >&2; exit 2; }

seeds="$build/seeds"
rm -rf "$seeds"
mkdir -p "$seeds" "$build/corpus" "$build/artifacts"
scenes=("$root"/examples/*.yaml "$root"/bench/scenes/*.yaml "$root"/bench/net_scenes/*.yaml
        "$root"/tests/data/*.yaml)
cp "${scenes[@]}" "$seeds"/
find "$root/fuzz/regressions" -type f ! -name README.md -exec cp {} "$seeds"/ \;
# Every key the seed scenes use, as a libFuzzer dictionary.
grep -ohE '[a-z_]+:' "${scenes[@]}" | sort -u | sed 's/.*/"&"/' >"$build/scene.dict"

echo "run-fuzzer.sh: $(ls "$seeds" | wc -l) seeds, $(wc -l <"$build/scene.dict") dictionary" \
  "entries, ${seconds} s" >&2
# In fork mode (one job) a slow unit (over 10 s) is written to the artifacts and the fuzzing goes
# on, so that one slow input does not end the run. Crashes, sanitizer reports and running out of
# memory still stop it. Replay a slow unit with the optimised build's fuzz/ancfnet_fuzz_replay to
# tell a hang from an input that is only slow under the sanitizers.
"$fuzzer" "$build/corpus" "$seeds" -dict="$build/scene.dict" -max_total_time="$seconds" \
  -timeout=10 -rss_limit_mb=4096 -max_len=65536 -artifact_prefix="$build/artifacts/" \
  -fork=1 -ignore_timeouts=1 -print_final_stats=1
