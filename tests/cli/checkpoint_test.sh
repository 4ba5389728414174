#!/usr/bin/env bash
# Checkpoint and restart, bit for bit (docs/reliability.md, "Checkpoints"):
# - the pendulum with --checkpoint-every 0.3 s writes the same outputs as without (taking
#   checkpoints changes nothing); its last checkpoint (t = 0.9 s) continued with --restart in a
#   copy of its outputs gives probes.csv, cables.pvd, every frame and summary.json's counts byte
#   for byte as the run that never stopped (the rows written after the checkpoint are cut back);
# - the S3 net drop (contact with friction, the adaptive Jacobian, energy step control) with
#   --checkpoint-every 0.05 s, stopped by SIGINT once three output rows exist, writes a checkpoint
#   when it stops (exit 130); continued from it, its outputs match those of the run never stopped;
# - refused with exit 2 and a message: a checkpoint of another scene (both named), a truncated
#   one, a damaged one, --checkpoint-every for a static analysis or below the time step.
# Usage: bash tests/cli/checkpoint_test.sh <ancfnet binary> <repo root>
set -euo pipefail

ancfnet="${1:?usage: checkpoint_test.sh <ancfnet binary> <repo root>}"
root="${2:?usage: checkpoint_test.sh <ancfnet binary> <repo root>}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# same_outputs EXPECTED ACTUAL WHAT: every output byte for byte (summary.json: all but the
# wall-clock times and the checkpoint), the same files present.
same_outputs() {
  local expected="$1" actual="$2" what="$3"
  diff -rq -x summary.json -x 'checkpoint.bin*' "$expected" "$actual" >"$work/diff" ||
    fail "$what: outputs differ: $(head -3 "$work/diff")"
  python3 - "$expected/summary.json" "$actual/summary.json" "$what" <<'PY'
import json, sys
expected, actual = (json.load(open(p)) for p in sys.argv[1:3])
for s in (expected, actual):
    for key in ("wall_time_s", "output_time_s", "wall_time", "output_time"):
        s.pop(key, None)
    s.get("statistics", {}).pop("wall_time_s", None)
if expected != actual:
    diff = [k for k in expected if expected.get(k) != actual.get(k)]
    sys.exit(f"FAIL: {sys.argv[3]}: summary.json differs in {diff}")
PY
}

# expect_refusal WHAT PATTERN COMMAND...: exit 2 and PATTERN in stderr.
expect_refusal() {
  local what="$1" pattern="$2" status=0
  shift 2
  "$@" -q 2>"$work/stderr" >/dev/null || status=$?
  [[ $status -eq 2 ]] || fail "$what: exit code $status, expected 2: $(cat "$work/stderr")"
  grep -q -- "$pattern" "$work/stderr" ||
    fail "$what: message lacks '$pattern': $(cat "$work/stderr")"
}

pendulum="$root/examples/pendulum.yaml"
# The S3 net drop to its landing (0.3 s of its 1 s), to keep the test short.
net="$work/net_drop_sphere.yaml"
sed 's/^  end_time: 1.0$/  end_time: 0.3/' "$root/examples/net_drop_sphere.yaml" >"$net"
grep -q "end_time: 0.3" "$net" || fail "could not shorten the S3 scene"

# Periodic checkpoints.
"$ancfnet" run "$pendulum" -o "$work/pendulum" -q || fail "pendulum: exit code $?"
"$ancfnet" run "$pendulum" -o "$work/pendulum_ckpt" -q --checkpoint-every 0.3 ||
  fail "pendulum with checkpoints: exit code $?"
[[ -f "$work/pendulum_ckpt/checkpoint.bin" && ! -e "$work/pendulum_ckpt/checkpoint.bin.tmp" ]] ||
  fail "pendulum: no checkpoint.bin, or its temporary file left"
same_outputs "$work/pendulum" "$work/pendulum_ckpt" "pendulum with checkpoints"
cp -r "$work/pendulum_ckpt" "$work/pendulum_restart"
"$ancfnet" run "$pendulum" -o "$work/pendulum_restart" -q \
  --restart "$work/pendulum_ckpt/checkpoint.bin" || fail "pendulum restart: exit code $?"
same_outputs "$work/pendulum" "$work/pendulum_restart" "pendulum restarted at t = 0.9 s"

# A checkpoint written when SIGINT stops the run.
"$ancfnet" run "$net" -o "$work/net" -q || fail "net: exit code $?"
"$ancfnet" run "$net" -o "$work/net_stopped" -q --checkpoint-every 0.05 2>"$work/stderr_int" &
pid=$!
for _ in $(seq 600); do
  [[ -f "$work/net_stopped/probes.csv" && $(wc -l <"$work/net_stopped/probes.csv") -ge 4 ]] && break
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.1
done
kill -s INT "$pid" 2>/dev/null || fail "net: the run ended before the signal"
status=0
wait "$pid" || status=$?
[[ $status -eq 130 ]] || fail "net: exit code $status after SIGINT, expected 130"
grep -q -- "--restart" "$work/stderr_int" ||
  fail "net: no hint how to continue: $(cat "$work/stderr_int")"
[[ -f "$work/net_stopped/checkpoint.bin" ]] || fail "net: no checkpoint after SIGINT"
"$ancfnet" run "$net" -o "$work/net_stopped" -q --restart "$work/net_stopped/checkpoint.bin" ||
  fail "net restart: exit code $?"
same_outputs "$work/net" "$work/net_stopped" "net stopped by SIGINT and restarted"

# Refusals.
expect_refusal "another scene" "not of $net" \
  "$ancfnet" run "$net" -o "$work/other" --restart "$work/pendulum_ckpt/checkpoint.bin"
grep -q "pendulum.yaml" "$work/stderr" || fail "another scene: the checkpoint's scene is not named"
[[ ! -e "$work/other" ]] || fail "another scene: the output directory was created"
head -c 200 "$work/pendulum_ckpt/checkpoint.bin" >"$work/truncated.bin"
expect_refusal "truncated" "truncated checkpoint" \
  "$ancfnet" run "$pendulum" -o "$work/pendulum_restart" --restart "$work/truncated.bin"
python3 - "$work/pendulum_ckpt/checkpoint.bin" "$work/damaged.bin" <<'PY'
import sys
data = bytearray(open(sys.argv[1], "rb").read())
data[-100] ^= 0xFF
open(sys.argv[2], "wb").write(data)
PY
expect_refusal "damaged" "checksum" \
  "$ancfnet" run "$pendulum" -o "$work/pendulum_restart" --restart "$work/damaged.bin"
expect_refusal "missing outputs" "probes.csv" \
  "$ancfnet" run "$pendulum" -o "$work/empty" --restart "$work/pendulum_ckpt/checkpoint.bin"
expect_refusal "static" "dynamic analyses" \
  "$ancfnet" run "$root/examples/cantilever_static.yaml" -o "$work/static" --checkpoint-every 1
expect_refusal "below the time step" "at least the time step" \
  "$ancfnet" run "$pendulum" -o "$work/small" --checkpoint-every 1e-9
echo "checkpoint test passed"
