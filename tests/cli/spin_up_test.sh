#!/usr/bin/env bash
# End-to-end check of the spin-up benchmark: `ancfnet run examples/spin_up.yaml` (a beam on a
# rotating_clamp), `ancfnet assumed-modes` (diverges at Ω = 6 rad/s, completes at 0.5 rad/s) and
# tools/plot_spin_up.py (the largest tip lag, 0.574 m, between 0.5 and 0.65 m); exit code 2 for a
# bad hub in a scene.
# Usage: bash tests/cli/spin_up_test.sh <ancfnet binary> <repo root>
set -euo pipefail

ancfnet="${1:?usage: spin_up_test.sh <ancfnet binary> <repo root>}"
root="${2:?usage: spin_up_test.sh <ancfnet binary> <repo root>}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

"$ancfnet" run "$root/examples/spin_up.yaml" -o "$work/out" -q || fail "ancfnet run exited with $?"
"$ancfnet" assumed-modes -o "$work/amm.csv" >"$work/amm.txt" || fail "assumed-modes exited with $?"
grep -q "diverged" "$work/amm.txt" || fail "the linear model did not diverge: $(cat "$work/amm.txt")"
"$ancfnet" assumed-modes --rate 0.5 -o "$work/slow.csv" >"$work/slow.txt"
grep -q "samples" "$work/slow.txt" || fail "the slow spin-up did not complete: $(cat "$work/slow.txt")"

/usr/bin/python3 "$root/tools/plot_spin_up.py" "$work/out/probes.csv" --rate 6 --time 15 \
  --assumed-modes "$work/amm.csv" -o "$work/spin_up.png" >"$work/plot.txt" ||
  fail "plot_spin_up.py exited with $?"
[[ -s "$work/spin_up.png" ]] || fail "spin_up.png missing"
/usr/bin/python3 - "$work/plot.txt" <<'PY' || fail "largest deflection out of range: $(cat "$work/plot.txt")"
import sys
value = float(open(sys.argv[1]).read().split("largest tip deflection")[1].split()[0])
assert 0.5 < value < 0.65, value
PY

sed 's/axis: \[0, 0, 1\]/axis: [0, 0, 0]/' "$root/examples/spin_up.yaml" >"$work/bad.yaml"
status=0
"$ancfnet" check "$work/bad.yaml" >/dev/null 2>"$work/stderr" || status=$?
[[ $status -eq 2 ]] || fail "expected exit code 2 for a zero hub axis, got $status"
grep -q "axis" "$work/stderr" || fail "no message for the axis: $(cat "$work/stderr")"

echo "spin_up: OK"
