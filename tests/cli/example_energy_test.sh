#!/usr/bin/env bash
# Energy is a first-class invariant: each example runs with its default settings and keeps its
# balance B = kinetic + strain + gravity + dissipated − work within 1 % of its energy scale (the
# largest |kinetic| + |strain| + |gravity| + |work| + dissipated over the run) at every output.
# Left out, with the reason (docs/validation.md, "Energy balance of the examples"): the capture
# demo (net_capture, about a minute; its balance is in docs/benchmarks.md);
# cantilever_static and cantilever_modes are not dynamic.
# Usage: bash tests/cli/example_energy_test.sh <ancfnet binary> <repo root>
set -euo pipefail

ancfnet="${1:?usage: example_energy_test.sh <ancfnet binary> <repo root>}"
root="${2:?usage: example_energy_test.sh <ancfnet binary> <repo root>}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

for example in pendulum cantilever_dynamic cantilever_decay journal_bearing lugre_incline \
  spin_up tethered_target net_deploy slider_crank slider_crank_clearance net_drop_sphere; do
  (cd "$root/examples" && "$ancfnet" run "$example.yaml" -o "$work/$example" -q) ||
    { echo "FAIL: $example: exit code $?" >&2; exit 1; }
  python3 - "$work/$example/probes.csv" "$example" <<'PY'
import csv, sys

path, example = sys.argv[1], sys.argv[2]
rows = list(csv.DictReader(open(path)))
terms = ("kinetic", "strain", "gravity", "work", "dissipated")
columns = [f"energy.{t}" for t in terms]
if not rows or any(c not in rows[0] for c in columns):
    sys.exit(f"FAIL: {example}: probes.csv has no energy probe (columns energy.kinetic, ...)")
def balance(row):
    k, s, g, w, d = (float(row[c]) for c in columns)
    return k + s + g + d - w
scale = max(sum(abs(float(row[c])) for c in columns) for row in rows)
start = balance(rows[0])
worst = max(abs(balance(row) - start) for row in rows)
print(f"{example}: balance drift {100 * worst / scale:.3f} % of the scale {scale:.4g} J")
if not worst <= 0.01 * scale:
    sys.exit(f"FAIL: {example}: the balance drifts by {worst:.3g} J, more than 1 % of {scale:.3g} J")
PY
done
echo "example energy test passed"
