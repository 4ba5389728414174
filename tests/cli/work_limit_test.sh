#!/usr/bin/env bash
# A dynamic run whose estimated work ((end_time / time_step) steps × coordinates) is beyond 10¹²
# unknown-steps is refused by `run` and `check` before anything runs (exit 2, the estimate and
# the hint --force, at time_step); `run --force` starts it (stopped here by SIGINT: exit 130).
# The scene is the S3 net drop with 40 × 40 meshes and time_step 1e-8 s.
# Usage: bash tests/cli/work_limit_test.sh <ancfnet binary> <repo root>
set -euo pipefail

ancfnet="${1:?usage: work_limit_test.sh <ancfnet binary> <repo root>}"
root="${2:?usage: work_limit_test.sh <ancfnet binary> <repo root>}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

sed -e 's/^    meshes: 10$/    meshes: 40/' -e 's/^  time_step: .*$/  time_step: 1.0e-8/' \
  "$root/examples/net_drop_sphere.yaml" >"$work/scene.yaml"
grep -q "meshes: 40" "$work/scene.yaml" && grep -q "time_step: 1.0e-8" "$work/scene.yaml" ||
  fail "test setup: scene not changed"

for command in run check; do
  status=0
  if [[ $command == run ]]; then
    "$ancfnet" run "$work/scene.yaml" -o "$work/out_run" -q 2>"$work/stderr" || status=$?
  else
    "$ancfnet" check "$work/scene.yaml" 2>"$work/stderr" >/dev/null || status=$?
  fi
  [[ $status -eq 2 ]] || fail "$command: exit code $status, expected 2: $(cat "$work/stderr")"
  grep -q "scene.yaml:[0-9]*:[0-9]*: .* unknown-steps, above the limit of 1e+12 .*--force (key 'time_step')" \
    "$work/stderr" || fail "$command: message: $(cat "$work/stderr")"
done
[[ ! -e "$work/out_run" ]] || fail "run: the output directory was created before the refusal"

status=0
timeout --preserve-status -s INT 20 "$ancfnet" run "$work/scene.yaml" -o "$work/forced" -q --force 2>"$work/stderr" ||
  status=$?
[[ $status -eq 130 ]] ||
  fail "run --force: exit code $status, expected 130 (stopped by SIGINT): $(cat "$work/stderr")"
echo "work limit test passed"
