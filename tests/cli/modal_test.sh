#!/usr/bin/env bash
# End-to-end check of `ancfnet modal` on examples/cantilever_modes.yaml: the table, modes.json
# (first bending pair at Euler–Bernoulli's 8.1799 Hz within 0.1 %, ζ = ω τ / 2), one VTK frame per
# mode, and exit code 2 for a bad option or scene.
# Usage: bash tests/cli/modal_test.sh <ancfnet binary> <repo root>
set -euo pipefail

ancfnet="${1:?usage: modal_test.sh <ancfnet binary> <repo root>}"
root="${2:?usage: modal_test.sh <ancfnet binary> <repo root>}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

"$ancfnet" modal "$root/examples/cantilever_modes.yaml" --modes 4 -o "$work/out" >"$work/stdout" ||
  fail "ancfnet modal exited with $?"
grep -q "8.1799" "$work/stdout" || fail "no first frequency in the table: $(cat "$work/stdout")"
[[ -s "$work/out/modes.pvd" ]] || fail "modes.pvd missing"
for i in 0 1 2 3; do
  [[ -s "$work/out/modes_00000$i.vtp" ]] || fail "modes_00000$i.vtp missing"
done
/usr/bin/python3 - "$work/out/modes.json" <<'PY' || fail "modes.json wrong"
import json, math, sys
modes = json.load(open(sys.argv[1]))["modes"]
assert len(modes) == 4, modes
f = modes[0]["frequency_hz"]
assert abs(f / 8.179899306 - 1) < 1e-3, f
zeta = modes[0]["damping_ratio"]
assert abs(zeta / (0.5 * 2 * math.pi * f * 2e-5) - 1) < 1e-5, zeta
assert abs(modes[1]["frequency_hz"] / f - 1) < 1e-6  # the other plane
PY

for args in "--modes 0" "--about nowhere" "--modes 100000"; do
  status=0
  # shellcheck disable=SC2086
  "$ancfnet" modal "$root/examples/cantilever_modes.yaml" $args -o "$work/bad" \
    >/dev/null 2>"$work/stderr" || status=$?
  [[ $status -eq 2 ]] || fail "expected exit code 2 for '$args', got $status"
done
grep -q "unknowns" "$work/stderr" || fail "no message for too many modes: $(cat "$work/stderr")"

echo "modal: OK"
