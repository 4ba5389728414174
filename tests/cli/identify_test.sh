#!/usr/bin/env bash
# `ancfnet identify`: a probes.csv with three known damped modes (1.3, 8.2, 23 Hz; ζ = 1, 2, 3 %)
# after 0.5 s of forcing, in two columns that share the poles, is identified back from --from 0.5
# (frequencies within 1e-6 relative, ζ within 1e-6) in the table and in the JSON file; bad input
# exits with code 2 and one line on stderr.
# Usage: bash tests/cli/identify_test.sh <ancfnet binary> <repo root>
set -euo pipefail

ancfnet="${1:?usage: identify_test.sh <ancfnet binary> <repo root>}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
python=/usr/bin/python3

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

"$python" - "$work/probes.csv" <<'PY'
import sys
import numpy as np
t = np.arange(1200) / 400.0
modes = [(1.3, 0.01, 1.0, 0.3), (8.2, 0.02, 0.8, -1.1), (23.0, 0.03, 0.6, 2.0)]
def decay(t, scale):
    y = np.zeros_like(t)
    for f, z, a, p in modes:
        w = 2 * np.pi * f
        y += scale * a * np.exp(-z * w * t) * np.cos(w * np.sqrt(1 - z * z) * t + p)
    return y
forced = t < 0.5
tip_z = np.where(forced, 5.0 * np.sin(40.0 * t), decay(t - 0.5, 1.0) - 0.3)
tip_x = np.where(forced, 0.0, decay(t - 0.5, 0.01))
with open(sys.argv[1], "w") as f:
    f.write("time,tip.x,tip.y,tip.z\n")
    for row in zip(t, tip_x, 0 * t, tip_z):
        f.write(",".join(repr(float(v)) for v in row) + "\n")
PY

"$ancfnet" identify "$work/probes.csv" --columns tip.z,tip.x --modes 3 --from 0.5 \
  -o "$work/modes.json" >"$work/stdout" || fail "identify exited with $?"
grep -q "1000 samples from t = 0.5 s" "$work/stdout" || fail "no sample line: $(cat "$work/stdout")"
# The table: mode, f [Hz], ζ [%], one amplitude per column.
read -r _ f1 z1 a1 _ < <(grep -E '^ +1 ' "$work/stdout")
[[ $f1 == 1.3 && $z1 == 1.0000 && $a1 == 1 ]] || fail "mode 1 row: $f1 $z1 $a1"
read -r _ f3 z3 _ < <(grep -E '^ +3 ' "$work/stdout")
[[ $f3 == 23 && $z3 == 3.0000 ]] || fail "mode 3 row: $f3 $z3"

"$python" - "$work/modes.json" <<'PY' || fail "modes.json does not hold the modes"
import json, sys
d = json.load(open(sys.argv[1]))
assert d["columns"] == ["tip.z", "tip.x"], d["columns"]
assert d["samples"] == 1000 and abs(d["time_step"] - 0.0025) < 1e-15
expected = [(1.3, 0.01, 1.0), (8.2, 0.02, 0.8), (23.0, 0.03, 0.6)]
assert len(d["modes"]) == 3
for m, (f, z, a) in zip(d["modes"], expected):
    assert abs(m["frequency_hz"] - f) < 1e-6 * f, m
    assert abs(m["damping_ratio"] - z) < 1e-6, m
    assert abs(m["amplitude"]["tip.z"] - a) < 1e-6, m
    assert abs(m["amplitude"]["tip.x"] - 0.01 * a) < 1e-8, m
PY

# Exit code 2 and one line on stderr naming what is wrong.
expect_input_error() {
  local text="$1"
  shift
  local status=0
  "$ancfnet" "$@" >"$work/out" 2>"$work/err" || status=$?
  [[ $status -eq 2 ]] || fail "ancfnet $* exited with $status, expected 2: $(cat "$work/err")"
  [[ $(wc -l <"$work/err") -eq 1 ]] || fail "ancfnet $*: stderr is not one line: $(cat "$work/err")"
  grep -qF -- "$text" "$work/err" || fail "ancfnet $*: expected '$text' in: $(cat "$work/err")"
}
csv="$work/probes.csv"
expect_input_error "no column 'tip.q'; did you mean" identify "$csv" --columns tip.q --modes 1
expect_input_error "columns: tip.x, tip.y, tip.z" identify "$csv" --columns tip.q --modes 1
expect_input_error "cannot open" identify "$work/absent.csv" --columns tip.z --modes 1
expect_input_error "number of modes must be" identify "$csv" --columns tip.z --modes 0
expect_input_error "too few" identify "$csv" --columns tip.z --modes 3 --from 0.5 --to 0.52
expect_input_error "'tip.y' is constant" identify "$csv" --columns tip.y --modes 1
expect_input_error "no row with" identify "$csv" --columns tip.z --modes 1 --from 10
# A command-line error is CLI11's message (two lines), still exit code 2.
status=0
"$ancfnet" identify "$csv" --columns tip.z >/dev/null 2>"$work/err" || status=$?
[[ $status -eq 2 ]] && grep -q -- "--modes is required" "$work/err" ||
  fail "identify without --modes exited with $status: $(cat "$work/err")"
echo "identify: all checks passed"
