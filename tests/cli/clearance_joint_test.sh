#!/usr/bin/env bash
# End-to-end check of clearance joints: `ancfnet run examples/journal_bearing.yaml` (a pin
# rattling in the bearing at the tip of a flexible arm) completes, its joint probe shows the
# journal's orbit within the clearance up to a small penetration, impacts and free flight, and the
# energy balance holds to 1 % of the pin's launch energy; invalid joints (clearance ≤ 0, journal
# radius ≤ clearance, zero axis, unknown body or cable) exit with 2 and name file, line and key.
# Usage: bash tests/cli/clearance_joint_test.sh <ancfnet binary> <repo root>
set -euo pipefail

ancfnet="${1:?usage: clearance_joint_test.sh <ancfnet binary> <repo root>}"
root="${2:?usage: clearance_joint_test.sh <ancfnet binary> <repo root>}"
scene="$root/examples/journal_bearing.yaml"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

"$ancfnet" run "$scene" -o "$work/out" -q || fail "ancfnet run exited with $?"
grep -q '"status": "completed"' "$work/out/summary.json" || fail "run did not complete"
grep -q '"clearance_joint"' "$work/out/summary.json" || fail "no joint probe in summary.json"
/usr/bin/python3 - "$work/out/probes.csv" <<'PY' || fail "joint probe out of range"
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
c = 0.5e-3
modes = {int(float(r["joint.mode"])) for r in rows}
assert {0, 2} <= modes, modes                       # free flight and impacts
for r in rows:
    e = math.hypot(float(r["joint.ex"]), float(r["joint.ey"]))
    assert e < 1.1 * c, e                           # the orbit stays in the clearance circle
    assert abs(float(r["joint.penetration"]) - (e - c)) < 1e-9
    assert float(r["joint.normal_force"]) >= 0.0
launch = 0.5 * 0.5 * (0.2**2 + 0.1**2) + 0.5 * 1e-4 * 30**2
def balance(r):
    return sum(float(r["energy." + k]) for k in ("kinetic", "strain", "gravity", "dissipated")) \
        - float(r["energy.work"])
drift = max(abs(balance(r) - balance(rows[0])) for r in rows)
assert drift < 0.01 * launch, (drift, launch)
PY

# Invalid joints, each the example with one mistake: exit 2, one line FILE:LINE:COL naming the key.
source "$root/tests/cli/expect_scene_error.sh"

expect_error negative_clearance 's/clearance: 0.5e-3/clearance: -0.5e-3/' "clearance: -" "clearance"
expect_error radius_below_clearance 's/journal_radius: 0.01/journal_radius: 0.4e-3/' \
  "journal_radius:" "journal_radius"
expect_error zero_axis 's/axis: \[0, 0, 1\]/axis: [0, 0, 0]/' "axis: \[0, 0, 0\]" "axis"
expect_error unknown_body 's/journal: {body: pin}/journal: {body: pun}/' "journal: \{body: pun" \
  "no rigid body named 'pun'"
expect_error unknown_cable 's/bearing: arm.end/bearing: ram.end/' "bearing: ram.end" "ram"

echo "clearance_joint: OK"
