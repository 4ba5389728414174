#!/usr/bin/env bash
# End-to-end checks of `ancfnet run`, `ancfnet static` and `ancfnet check` on the cantilever of
# examples/cantilever_static.yaml: exit codes, summary.json, probes.csv and the VTK series.
#  - static: the tip of the elastica at P L² / EI = 2 (Mattiasson 1981: w/L = 0.49346,
#    u/L = 0.16064), to ±1.5 mm;
#  - dynamic (generalized-α, load applied suddenly): velocity and energy probe columns, and the
#    energy balance kinetic + strain + gravity + dissipated − work within 1 % of the largest work
#    in every row (the code achieves about 0.1 %: the missing part is the numerical damping of
#    generalized-α with ρ∞ = 0.9);
#  - `static` on the dynamic scene solves the static problem; `check` describes the model.
# Usage: bash tests/cli/run_outputs_test.sh <ancfnet binary> <repo root>
set -euo pipefail

ancfnet="${1:?usage: run_outputs_test.sh <ancfnet binary> <repo root>}"
root="${2:?usage: run_outputs_test.sh <ancfnet binary> <repo root>}"
scene="$root/examples/cantilever_static.yaml"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# Runs the ancfnet command "$@" and fails unless it exits with code 0.
run_ok() {
  local status=0
  "$ancfnet" "$@" >"$work/stdout" 2>"$work/stderr" || status=$?
  [[ $status -eq 0 ]] || fail "ancfnet $* exited with $status: $(cat "$work/stderr")"
}

# Checks summary.json, probes.csv and the VTK series in directory $1 with analysis $2, the probe
# columns $3 (comma-separated, after time) and output interval $4 (0: every step). Prints
# nothing; exits non-zero with a message.
check_outputs() {
  python3 - "$1" "$2" "$3" "$4" <<'PY'
import csv, json, math, os, sys
import xml.etree.ElementTree as ET

out, analysis, columns, interval = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
def fail(message):
    sys.exit(f"FAIL: {out}: {message}")
def reject(constant):
    fail(f"summary.json holds {constant}")

for name in ("summary.json", "probes.csv", "cables.pvd"):
    if not os.path.isfile(os.path.join(out, name)):
        fail(f"{name} missing")
with open(os.path.join(out, "summary.json")) as f:
    summary = json.load(f, parse_constant=reject)
for key in ("status", "analysis", "energy", "steps", "newton_iterations", "wall_time_s", "probes"):
    if key not in summary:
        fail(f"summary.json has no key '{key}'")
if summary["status"] != "completed":
    fail(f"status is {summary['status']!r}, not 'completed'")
if summary["analysis"] != analysis:
    fail(f"analysis is {summary['analysis']!r}, not {analysis!r}")
for key in ("kinetic", "strain", "gravity", "work", "dissipated"):
    if not isinstance(summary["energy"].get(key), float):
        fail(f"summary energy.{key} is not a number: {summary['energy'].get(key)!r}")
if not (isinstance(summary["steps"], int) and summary["steps"] >= 1):
    fail(f"steps = {summary['steps']!r}")
if not (isinstance(summary["newton_iterations"], int) and
        summary["newton_iterations"] >= summary["steps"]):
    fail(f"newton_iterations = {summary['newton_iterations']!r} < steps")
if not (isinstance(summary["wall_time_s"], float) and summary["wall_time_s"] >= 0):
    fail(f"wall_time_s = {summary['wall_time_s']!r}")

with open(os.path.join(out, "probes.csv")) as f:
    lines = f.read().splitlines()
expected_header = "time," + columns
if lines[0] != expected_header:
    fail(f"probes.csv header is {lines[0]!r}, expected {expected_header!r}")
rows = list(csv.reader(lines[1:]))
# One row for the initial state, then one per step or one per output interval.
expected_rows = (summary["steps"] + 1 if interval == 0 else
                 round(summary["time"] / interval) + 1)
if len(rows) != expected_rows:
    fail(f"probes.csv has {len(rows)} rows, expected {expected_rows} (steps {summary['steps']}, "
         f"output interval {interval})")
times = []
for i, row in enumerate(rows):
    if len(row) != len(lines[0].split(",")):
        fail(f"probes.csv row {i + 1} has {len(row)} fields")
    values = [float(x) for x in row]
    if not all(math.isfinite(x) for x in values):
        fail(f"probes.csv row {i + 1} holds a non-finite value: {row}")
    times.append(values[0])
if times[0] != 0.0 or any(b <= a for a, b in zip(times, times[1:])):
    fail("probes.csv times do not start at 0 and increase")
if abs(times[-1] - summary["time"]) > 1e-12:
    fail(f"summary time {summary['time']} is not the last row's time {times[-1]}")
if interval > 0:
    for i, t in enumerate(times):
        if abs(t - i * interval) > 1e-9:
            fail(f"probes.csv row {i + 1} at t = {t}, expected {i * interval}")

pvd = ET.parse(os.path.join(out, "cables.pvd")).getroot()
datasets = pvd.findall("./Collection/DataSet")
if len(datasets) != len(rows):
    fail(f"cables.pvd lists {len(datasets)} frames for {len(rows)} probe rows")
for i, dataset in enumerate(datasets):
    path = os.path.join(out, dataset.get("file"))
    if not os.path.isfile(path):
        fail(f"cables.pvd references a missing file {dataset.get('file')}")
    if abs(float(dataset.get("timestep")) - times[i]) > 1e-12:
        fail(f"frame {i} has time {dataset.get('timestep')}, probes.csv {times[i]}")
for dataset in datasets:
    vtp = ET.parse(os.path.join(out, dataset.get("file"))).getroot()
    piece = vtp.find("./PolyData/Piece")
    if vtp.get("type") != "PolyData" or piece is None:
        fail(f"{dataset.get('file')} is not VTK PolyData")
    points = vtp.find("./PolyData/Piece/Points/DataArray").text.split()
    if len(points) != 3 * int(piece.get("NumberOfPoints")):
        fail(f"{dataset.get('file')}: {len(points)} coordinates for "
             f"{piece.get('NumberOfPoints')} points")
    if not all(math.isfinite(float(x)) for x in points):
        fail(f"{dataset.get('file')} holds a non-finite coordinate")
PY
}

# 1. The static cantilever of the issue.
out="$work/static"
run_ok run "$scene" -o "$out" -q
[[ ! -s "$work/stdout" ]] || fail "run -q printed to stdout: $(cat "$work/stdout")"
check_outputs "$out" static "tip.x,tip.y,tip.z" 0 || exit 1
python3 - "$out/summary.json" <<'PY' || exit 1
import json, sys
tip = json.load(open(sys.argv[1]))["probes"]["tip"]["position"]
if not (isinstance(tip, list) and len(tip) == 3):
    sys.exit(f"FAIL: probes.tip.position is {tip!r}, not [x, y, z]")
x, y, z = tip
# Mattiasson (1981), P L² / EI = 2: w/L = 0.49346, u/L = 0.16064 (L = 1 m).
if abs(z - (-0.49346)) > 0.0015:
    sys.exit(f"FAIL: tip z = {z:.6f} m, expected -0.4935 ± 0.0015 m")
if abs(x - (1.0 - 0.16064)) > 0.0015:
    sys.exit(f"FAIL: tip x = {x:.6f} m, expected 0.8394 ± 0.0015 m")
if abs(y) > 1e-9:
    sys.exit(f"FAIL: tip y = {y} m, expected 0")
PY
# Without -q the closing message names the output directory.
run_ok run "$scene" -o "$work/static_loud"
grep -q "completed" "$work/stdout" || fail "run without -q printed no closing message"

# 2. The same cantilever, dynamic: the load applied suddenly at t = 0.
dynamic="$work/cantilever_dynamic.yaml"
sed '/^probes:/,$d' "$scene" >"$dynamic"
cat >>"$dynamic" <<'YAML'
probes:
  - {name: tip, quantity: position, at: beam.end}
  - {name: tipv, quantity: velocity, at: beam.end}
  - {name: e, quantity: energy}
analysis: {type: dynamic, integrator: generalized_alpha, spectral_radius: 0.9, time_step: 1.0e-3, end_time: 1.0}
output: {interval: 1.0e-2}
YAML
grep -q "^materials:" "$dynamic" || fail "could not derive the dynamic scene from $scene"
out="$work/dynamic"
run_ok run "$dynamic" -o "$out" -q
check_outputs "$out" dynamic \
  "tip.x,tip.y,tip.z,tipv.vx,tipv.vy,tipv.vz,e.kinetic,e.strain,e.gravity,e.work,e.dissipated" \
  0.01 || exit 1
python3 - "$out/probes.csv" <<'PY' || exit 1
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
if abs(float(rows[-1]["time"]) - 1.0) > 1e-9:
    sys.exit(f"FAIL: the dynamic run ends at t = {rows[-1]['time']}, not 1.0")
max_work = max(abs(float(r["e.work"])) for r in rows)
if max_work < 10.0:  # P times a tip travel of some 0.1 m at least
    sys.exit(f"FAIL: the load did no work (max work {max_work} J)")
for r in rows:
    balance = (float(r["e.kinetic"]) + float(r["e.strain"]) + float(r["e.gravity"]) +
               float(r["e.dissipated"]) - float(r["e.work"]))
    if abs(balance) > 0.01 * max_work:
        sys.exit(f"FAIL: energy balance {balance:.4g} J at t = {r['time']} exceeds 1 % of the "
                 f"largest work {max_work:.4g} J")
# The bar swings, and the velocity probe is the rate of the position probe: central differences
# of tip.z over 0.02 s follow tipv.vz to about 15 % RMS (the motion has periods of some 0.1 s);
# a wrong column, sign or point would be far off.
t = [float(r["time"]) for r in rows]
z = [float(r["tip.z"]) for r in rows]
vz = [float(r["tipv.vz"]) for r in rows]
if max(abs(v) for v in vz) < 1.0:
    sys.exit(f"FAIL: tip vz never exceeds 1 m/s (max {max(abs(v) for v in vz)})")
errors = [(z[i + 1] - z[i - 1]) / (t[i + 1] - t[i - 1]) - vz[i] for i in range(1, len(rows) - 1)]
rms_error = (sum(e * e for e in errors) / len(errors)) ** 0.5
rms_vz = (sum(v * v for v in vz) / len(vz)) ** 0.5
if rms_error > 0.3 * rms_vz:
    sys.exit(f"FAIL: tipv.vz differs from d(tip.z)/dt by {rms_error:.3g} m/s RMS "
             f"(RMS speed {rms_vz:.3g} m/s)")
PY

# `static` overrides the analysis type of the file.
out="$work/dynamic_as_static"
run_ok static "$dynamic" -o "$out" -q
python3 - "$out/summary.json" <<'PY' || exit 1
import json, sys
s = json.load(open(sys.argv[1]))
if s["analysis"] != "static" or s["status"] != "completed":
    sys.exit(f"FAIL: `static` on a dynamic scene gave analysis {s['analysis']!r}, "
             f"status {s['status']!r}")
z = s["probes"]["tip"]["position"][2]
if abs(z + 0.49346) > 0.0015:
    sys.exit(f"FAIL: `static` on the dynamic scene: tip z = {z}, expected -0.4935")
PY

# 3. check: exit 0, a description of the model, and no output directory.
for file in "$scene" "$dynamic"; do
  run_ok check "$file"
  grep -q "beam" "$work/stdout" || fail "check $file does not name the cable: $(cat "$work/stdout")"
  grep -q "16 elements" "$work/stdout" || fail "check $file does not give the element count"
  grep -qi "analysis" "$work/stdout" || fail "check $file does not describe the analysis"
done
grep -q "dynamic" "$work/stdout" || fail "check on the dynamic scene does not say 'dynamic'"

echo "run_outputs: OK"
