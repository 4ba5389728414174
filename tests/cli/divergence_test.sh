#!/usr/bin/env bash
# Scenes on which the solver gives up: `ancfnet run` must exit with code 3, say on stderr at
# which time and why, keep the outputs written before the failure (summary.json with status
# "failed" and the message, the probes.csv rows, the VTK frames), and never write NaN or inf.
#  1. explicit Verlet at h = 1 ms on a steel cantilever whose stable step is a few µs, with the
#     step not allowed to shrink: the state grows without bound and overflows within a few steps;
#  2. generalized-α with a violent load, few Newton iterations and no step cuts allowed;
#  3. a scene whose very first output is not finite (a cable 1e300 m long, no probes): nothing
#     non-finite may reach the VTK frame or summary.json.
# Usage: bash tests/cli/divergence_test.sh <ancfnet binary> <repo root>
set -euo pipefail

ancfnet="${1:?usage: divergence_test.sh <ancfnet binary> <repo root>}"
root="${2:?usage: divergence_test.sh <ancfnet binary> <repo root>}"
scene="$root/examples/cantilever_static.yaml"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# expect_failure CASE MIN_ROWS: runs $work/CASE.yaml and checks the contract of a solver failure,
# with at least MIN_ROWS rows kept in probes.csv.
expect_failure() {
  local case="$1" min_rows="$2" out="$work/out_$1" status=0
  "$ancfnet" run "$work/$case.yaml" -o "$out" -q >"$work/stdout" 2>"$work/stderr" || status=$?
  local message
  message="$(cat "$work/stderr")"
  [[ $status -eq 3 ]] || fail "$case: exit code $status, expected 3; stderr: $message"
  [[ $message =~ t\ =\ [0-9] ]] || fail "$case: stderr does not say at which time: $message"
  # No NaN or infinity anywhere in the outputs (words such as "non-finite" are fine).
  if grep -Eiw -- '-?(nan|inf|infinity)' "$out"/probes.csv "$out"/summary.json \
    "$out"/*.vtp >"$work/nonfinite" 2>/dev/null; then
    fail "$case: non-finite values written: $(head -3 "$work/nonfinite")"
  fi
  python3 - "$out" "$min_rows" "$message" <<'PY' || exit 1
import csv, json, math, os, sys
import xml.etree.ElementTree as ET

out, min_rows, stderr = sys.argv[1], int(sys.argv[2]), sys.argv[3]
def fail(message):
    sys.exit(f"FAIL: {out}: {message}")
def reject(constant):
    fail(f"summary.json holds {constant}")

summary = json.load(open(os.path.join(out, "summary.json")), parse_constant=reject)
if summary.get("status") != "failed":
    fail(f"status is {summary.get('status')!r}, expected 'failed'")
message = summary.get("message", "")
if not message or message not in stderr:
    fail(f"summary message {message!r} is empty or not the one on stderr: {stderr!r}")

with open(os.path.join(out, "probes.csv")) as f:
    rows = list(csv.reader(f))[1:]
if len(rows) < min_rows:
    fail(f"probes.csv keeps {len(rows)} rows, expected at least {min_rows}")
for row in rows:
    if not all(math.isfinite(float(x)) for x in row):
        fail(f"probes.csv holds a non-finite row: {row}")
if rows and abs(float(rows[-1][0]) - summary["time"]) > 1e-12:
    fail(f"summary time {summary['time']} is not that of the last row kept ({rows[-1][0]})")
if rows and f"{float(rows[-1][0]):.9g}" not in stderr:
    fail(f"stderr does not give the time of the last output kept ({rows[-1][0]}): {stderr!r}")

pvd_path = os.path.join(out, "cables.pvd")
frames = ET.parse(pvd_path).getroot().findall("./Collection/DataSet") \
    if os.path.exists(pvd_path) else []
if len(frames) != len(rows):
    fail(f"{len(frames)} VTK frames for {len(rows)} probe rows")
for frame in frames:
    vtp = ET.parse(os.path.join(out, frame.get("file"))).getroot()
    points = vtp.find("./PolyData/Piece/Points/DataArray").text.split()
    if not all(math.isfinite(float(x)) for x in points):
        fail(f"{frame.get('file')} holds a non-finite coordinate")
PY
}

# 1. Explicit Verlet far above its stability limit.
sed '/^analysis:/,$d' "$scene" >"$work/explicit_unstable.yaml"
cat >>"$work/explicit_unstable.yaml" <<'YAML'
  - {name: e, quantity: energy}
analysis: {type: dynamic, integrator: explicit_verlet, time_step: 1.0e-3, min_time_step: 1.0e-3, end_time: 1.0}
output: {interval: 1.0e-3}
YAML
expect_failure explicit_unstable 2
grep -qi "finite" "$work/stderr" || fail "explicit_unstable: stderr does not say why: $(cat "$work/stderr")"

# 2. Generalized-α: Newton cannot converge in 5 iterations and the step may not be cut.
sed '/^analysis:/,$d; s/force: \[0, 0, -333.333\]/force: [0, 0, -3.0e7]/' "$scene" \
  >"$work/newton_fails.yaml"
grep -q -- "-3.0e7" "$work/newton_fails.yaml" || fail "newton_fails: test setup: load not changed"
cat >>"$work/newton_fails.yaml" <<'YAML'
analysis: {type: dynamic, integrator: generalized_alpha, time_step: 1.0e-2, min_time_step: 1.0e-2, end_time: 1.0, max_iterations: 5}
YAML
expect_failure newton_fails 1
grep -q "convergence" "$work/stderr" || fail "newton_fails: stderr does not say why: $(cat "$work/stderr")"

# 3. A first output that is not finite: refused, not written.
sed '/^probes:/,/quantity: position/d; s/end: \[1, 0, 0\]/end: [1.0e300, 0, 0]/' "$scene" \
  >"$work/overflow.yaml"
grep -q "1.0e300" "$work/overflow.yaml" || fail "overflow: test setup: end not changed"
! grep -q "^probes:" "$work/overflow.yaml" || fail "overflow: test setup: probes not removed"
expect_failure overflow 0

echo "divergence: OK"
