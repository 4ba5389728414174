#!/usr/bin/env bash
# End-to-end check of rigid bodies: `ancfnet run examples/tethered_target.yaml` (a free target
# towed by a prescribed chaser through a tether with fixed attachments) completes, writes the
# body probes (unit quaternions, the target pulled along +x) and the bodies' frames in the VTK
# files; static and modal analyses of it are refused with exit code 2.
# Usage: bash tests/cli/rigid_body_test.sh <ancfnet binary> <repo root>
set -euo pipefail

ancfnet="${1:?usage: rigid_body_test.sh <ancfnet binary> <repo root>}"
root="${2:?usage: rigid_body_test.sh <ancfnet binary> <repo root>}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

scene="$root/examples/tethered_target.yaml"
"$ancfnet" run "$scene" -o "$work/out" -q || fail "ancfnet run exited with $?"
grep -q '"status": "completed"' "$work/out/summary.json" || fail "run did not complete"
/usr/bin/python3 - "$work/out/probes.csv" <<'PY' || fail "body probes out of range"
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
for row in rows:
    q = [float(row["target." + k]) for k in ("qw", "qx", "qy", "qz")]
    assert abs(math.sqrt(sum(c * c for c in q)) - 1.0) < 1e-9, q
last = rows[-1]
assert float(last["time"]) == 20.0, last["time"]
assert float(last["target.x"]) > 1.0, last["target.x"]       # towed along +x
assert float(last["target_rates.vx"]) > 0.0, last["target_rates.vx"]
PY
grep -q 'NumberOfLines="7"' "$work/out/cables_000000.vtp" ||
  fail "expected 1 cable + 2 × 3 body axes in the VTK frame"

for analysis in static modal; do
  status=0
  "$ancfnet" "$analysis" "$scene" -o "$work/$analysis" >/dev/null 2>"$work/stderr" || status=$?
  [[ $status -eq 2 ]] || fail "expected exit code 2 for $analysis with a free body, got $status"
  grep -q "free rigid body" "$work/stderr" || fail "no message: $(cat "$work/stderr")"
done

echo "rigid_body: OK"
