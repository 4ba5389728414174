#!/usr/bin/env bash
# End-to-end check of examples/slider_crank_clearance.yaml and its plots: the example runs (its
# orbit, impacts and energy are checked by SliderCrankClearance.TheExampleLosesEnergyOnlyWhile-
# TheJournalTouches), and tools/plot_slider_crank_clearance.py writes the slider acceleration
# against the ideal curve and the orbit; the script exits with 2 for a missing file or a probe
# CSV without the slider's and the joint's probes.
# Usage: bash tests/cli/plot_slider_crank_clearance_test.sh <ancfnet binary> <repo root>
set -euo pipefail

ancfnet="${1:?usage: plot_slider_crank_clearance_test.sh <ancfnet binary> <repo root>}"
root="${2:?usage: plot_slider_crank_clearance_test.sh <ancfnet binary> <repo root>}"
script="$root/tools/plot_slider_crank_clearance.py"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

(cd "$root/examples" && "$ancfnet" run slider_crank_clearance.yaml -o "$work/out" -q) ||
  fail "ancfnet run exited with $?"
grep -q '"status": "completed"' "$work/out/summary.json" || fail "run did not complete"

args=(--crank 0.05 --rod 0.12 --rate 523.5987755982989 --clearance 0.5e-3)
/usr/bin/python3 "$script" "$work/out/probes.csv" "${args[@]}" -o "$work/plots" >"$work/stdout" ||
  fail "plot_slider_crank_clearance.py exited with $?"
for name in slider_acceleration journal_orbit; do
  [[ -s "$work/plots/$name.png" ]] || fail "$name.png missing or empty"
  grep -q "$name.png" "$work/stdout" || fail "$name.png not printed"
done

printf 'time,x.vx\n0,1\n1,2\n2,3\n' >"$work/other.csv"
for input in "$work/missing.csv" "$work/other.csv"; do
  status=0
  /usr/bin/python3 "$script" "$input" "${args[@]}" 2>"$work/stderr" || status=$?
  [[ $status -eq 2 ]] || fail "expected exit code 2 for $input, got $status"
  grep -q "error" "$work/stderr" || fail "no error message for $input"
done

echo "plot_slider_crank_clearance: OK"
