#!/usr/bin/env bash
# Checks tools/plot_probes.py on a small hand-written probe CSV: one PNG per probe (and a path for
# position probes), and exit code 2
# for a missing or empty file.
# Usage: bash tests/cli/plot_probes_test.sh <ancfnet binary (unused)> <repo root>
set -euo pipefail

root="${2:?usage: plot_probes_test.sh <ancfnet binary> <repo root>}"
script="$root/tools/plot_probes.py"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

cat >"$work/probes.csv" <<'CSV'
time,tip.x,tip.y,tip.z,e.kinetic,e.strain,e.gravity,e.work,e.dissipated
0,1,0,0,0,0,0,0,0
0.1,0.99,0,-0.049,0.48,0.01,-0.49,0,0
0.2,0.96,0,-0.19,1.9,0.02,-1.92,0,0.001
0.3,0.91,0,-0.42,4.1,0.05,-4.15,0,0.002
CSV

/usr/bin/python3 "$script" "$work/probes.csv" -o "$work/plots" >"$work/stdout" ||
  fail "plot_probes.py exited with $?"
for name in tip tip_path e; do
  [[ -s "$work/plots/$name.png" ]] || fail "$name.png missing or empty"
  grep -q "$name.png" "$work/stdout" || fail "$name.png not printed"
done

# Without -o the plots go beside the CSV.
/usr/bin/python3 "$script" "$work/probes.csv" >/dev/null || fail "default OUTDIR run failed"
[[ -s "$work/tip.png" ]] || fail "tip.png not written beside the CSV"

for input in "$work/missing.csv" "$work/empty.csv"; do
  : >"$work/empty.csv"
  status=0
  /usr/bin/python3 "$script" "$input" 2>"$work/stderr" || status=$?
  [[ $status -eq 2 ]] || fail "expected exit code 2 for $input, got $status"
  grep -q "error" "$work/stderr" || fail "no error message for $input"
done

echo "plot_probes: OK"
