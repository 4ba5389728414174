#!/usr/bin/env bash
# The same scene, build and thread count give bit-identical outputs: the S3 net drop (contact
# with friction, step cuts) over its first 0.25 s (the first landings), run twice with one OpenMP thread and twice with
# two; probes.csv and every VTK frame must match byte for byte within each pair.
# Usage: bash tests/cli/determinism_test.sh <ancfnet binary> <repo root>
set -euo pipefail

ancfnet="${1:?usage: determinism_test.sh <ancfnet binary> <repo root>}"
root="${2:?usage: determinism_test.sh <ancfnet binary> <repo root>}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

sed 's/^  end_time: 1.0$/  end_time: 0.25/' "$root/examples/net_drop_sphere.yaml" >"$work/scene.yaml"
grep -q "end_time: 0.25" "$work/scene.yaml" || fail "test setup: end_time not changed"

for threads in 1 2; do
  for run in a b; do
    OMP_NUM_THREADS=$threads "$ancfnet" run "$work/scene.yaml" -o "$work/out_${threads}_$run" -q ||
      fail "$threads thread(s), run $run: exit code $?"
  done
  # Every output but summary.json (which holds wall times).
  diff -rq -x summary.json "$work/out_${threads}_a" "$work/out_${threads}_b" >"$work/diff" ||
    fail "$threads thread(s): outputs differ between two runs: $(head -3 "$work/diff")"
  [[ $(wc -l <"$work/out_${threads}_a/probes.csv") -eq 27 ]] ||
    fail "$threads thread(s): expected 26 output rows"
done
echo "determinism test passed"
