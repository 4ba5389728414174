#!/usr/bin/env bash
# End-to-end check of ideal joints: `ancfnet run examples/slider_crank.yaml` completes, reports
# the joints' drift (max_constraint_violation) below Newton's tolerance in summary.json, and keeps
# its energy balance (the crank drive's work counted) within 1 % of the largest kinetic energy;
# invalid joints (unknown body, zero axis, two joints of one name, a `between` of one side, a
# misspelt type) exit with 2 and name file, line and key; modal analysis and the implicit midpoint
# integrator refuse joints.
# Usage: bash tests/cli/ideal_joint_test.sh <ancfnet binary> <repo root>
set -euo pipefail

ancfnet="${1:?usage: ideal_joint_test.sh <ancfnet binary> <repo root>}"
root="${2:?usage: ideal_joint_test.sh <ancfnet binary> <repo root>}"
scene="$root/examples/slider_crank.yaml"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

"$ancfnet" run "$scene" -o "$work/out" -q || fail "ancfnet run exited with $?"
/usr/bin/python3 - "$work/out/summary.json" "$work/out/probes.csv" <<'PY' || fail "run out of bounds"
import csv, json, sys
summary = json.load(open(sys.argv[1]))
assert summary["status"] == "completed", summary["message"]
drift = summary["max_constraint_violation"]
assert 0.0 <= drift < 1e-12 + 1e-10 * 0.17, drift   # atol + rtol |c| at the farthest pin
rows = list(csv.DictReader(open(sys.argv[2])))
def balance(r):
    return sum(float(r["energy." + k]) for k in ("kinetic", "strain", "gravity", "dissipated")) \
        - float(r["energy.work"])
kinetic = max(float(r["energy.kinetic"]) for r in rows)
moved = max(abs(balance(r) - balance(rows[0])) for r in rows)
assert moved < 0.01 * kinetic, (moved, kinetic)
PY

# Invalid joints, each the example with one mistake: exit 2, one line FILE:LINE:COL naming the key.
source "$root/tests/cli/expect_scene_error.sh"

expect_error unknown_body 's/between: \[{body: crank}, {body: rod}\]/between: [{body: crank}, {body: rot}]/' \
  "body: rot" "no rigid body named 'rot'"
expect_error zero_axis 's/axis: \[1, 0, 0\]/axis: [0, 0, 0]/' "axis: \[0, 0, 0\]" "axis"
expect_error duplicate_name 's/name: piston_pin/name: crank_pin/' "name: crank_pin, type: spherical, between: \[\{body: rod" \
  "two joints are named 'crank_pin'"
expect_error one_side 's/between: \[{body: slider}, ground\]/between: [{body: slider}]/' \
  "between: \[\{body: slider\}\]" "between"
expect_error misspelt_type 's/type: line/type: lin/' "type: lin" "line"

# What does not support joints says so.
sed -e 's/integrator: generalized_alpha/integrator: midpoint/' "$scene" >"$work/midpoint.yaml"
status=0
"$ancfnet" run "$work/midpoint.yaml" -o "$work/midpoint" -q 2>"$work/stderr" || status=$?
[[ $status -eq 2 ]] || fail "implicit midpoint with joints: exit $status, expected 2"
grep -q "does not support ideal joints" "$work/stderr" || fail "midpoint: $(cat "$work/stderr")"

echo "ideal_joint: OK"
