#!/usr/bin/env bash
# Checks tools/plot_deployment.py on a small hand-written probe CSV: the PNG is written, the peak
# of the mouth area is found, and a missing column gives exit code 2 with a message.
# Usage: bash tests/cli/plot_deployment_test.sh <ancfnet binary (unused)> <repo root>
set -euo pipefail

root="${2:?usage: plot_deployment_test.sh <ancfnet binary> <repo root>}"
script="$root/tools/plot_deployment.py"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

cat >"$work/probes.csv" <<'CSV'
time,mouth.area,travel.distance,tension.tension,tension.thread
0,1,0,0,0
0.1,4,0.5,1,3
0.2,9.5,1.1,2,3
0.3,6,1.8,3,1
CSV

/usr/bin/python3 "$script" "$work/probes.csv" -o "$work/out/deploy.png" >"$work/stdout" ||
  fail "plot_deployment.py exited with $?"
[[ -s "$work/out/deploy.png" ]] || fail "deploy.png missing or empty"
grep -q "peak mouth area 9.5 m² at t = 0.2" "$work/stdout" || fail "peak not reported: $(cat "$work/stdout")"

status=0
/usr/bin/python3 "$script" "$work/probes.csv" --area net 2>"$work/stderr" >/dev/null || status=$?
[[ $status -eq 2 ]] || fail "expected exit code 2 for a missing probe, got $status"
grep -q "no column net.area" "$work/stderr" || fail "no message for a missing probe: $(cat "$work/stderr")"

echo "plot_deployment: OK"
