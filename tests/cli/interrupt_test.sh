#!/usr/bin/env bash
# A run stopped by SIGINT or SIGTERM finishes the step in progress, writes the state reached and
# stops cleanly: exit 130 / 143, summary.json with status "interrupted" and the signal in its
# message, and outputs that agree (as many probes.csv rows as frames in cables.pvd and
# contacts.pvd and as cables_*.vtp files, the last row at the summary's time, no NaN). The scene is
# the S3 net drop (about 10 s on one core); the signal is sent once three output rows exist.
# Usage: bash tests/cli/interrupt_test.sh <ancfnet binary> <repo root>
set -euo pipefail

ancfnet="${1:?usage: interrupt_test.sh <ancfnet binary> <repo root>}"
root="${2:?usage: interrupt_test.sh <ancfnet binary> <repo root>}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# interrupt SIGNAL EXPECTED_CODE
interrupt() {
  local signal="$1" expected="$2" out="$work/out_$1" status=0
  "$ancfnet" run "$root/examples/net_drop_sphere.yaml" -o "$out" -q 2>"$work/stderr_$signal" &
  local pid=$!
  # Wait (at most 60 s) until three output rows (header + 3 lines) are written.
  for _ in $(seq 600); do
    [[ -f "$out/probes.csv" && $(wc -l <"$out/probes.csv") -ge 4 ]] && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
  done
  kill -s "$signal" "$pid" 2>/dev/null || fail "$signal: the run ended before the signal"
  wait "$pid" || status=$?
  [[ $status -eq $expected ]] ||
    fail "$signal: exit code $status, expected $expected; stderr: $(cat "$work/stderr_$signal")"
  grep -q "interrupted by SIG$signal" "$work/stderr_$signal" ||
    fail "$signal: stderr does not say so: $(cat "$work/stderr_$signal")"
  python3 - "$out" "$signal" <<'PY'
import csv, glob, json, math, os, sys

out, signal = sys.argv[1], sys.argv[2]
def fail(message):
    sys.exit(f"FAIL: {signal}: {message}")

summary = json.load(open(os.path.join(out, "summary.json")))
if summary["status"] != "interrupted":
    fail(f"status {summary['status']!r}, expected 'interrupted'")
if signal not in summary["message"]:
    fail(f"message {summary['message']!r} does not name {signal}")
with open(os.path.join(out, "probes.csv")) as f:
    rows = list(csv.reader(f))[1:]
for row in rows:
    if not all(math.isfinite(float(x)) for x in row):
        fail(f"non-finite value in probes.csv: {row}")
frames = {name: open(os.path.join(out, f"{name}.pvd")).read().count("<DataSet")
          for name in ("cables", "contacts")}
files = len(glob.glob(os.path.join(out, "cables_*.vtp")))
if not (len(rows) == frames["cables"] == frames["contacts"] == files) or len(rows) < 4:
    fail(f"{len(rows)} probe rows, {frames} frames in the .pvd files, {files} cables_*.vtp")
if float(rows[-1][0]) != summary["time"]:
    fail(f"last row at t = {rows[-1][0]}, summary time {summary['time']}")
if summary["time"] >= 1.0:
    fail("the run was not interrupted before its end")
PY
}

interrupt INT 130
interrupt TERM 143
echo "interrupt test passed"
