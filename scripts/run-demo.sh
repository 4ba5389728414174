#!/usr/bin/env bash
# The README's demo: runs the main example (the flexible pendulum of Berzeri & Shabana 2000),
# plots its probes and says where everything is.
# Usage: scripts/run-demo.sh <ancfnet binary>   (called by `make demo` after the build)
set -euo pipefail

binary="${1:?usage: run-demo.sh <ancfnet binary>}"
root="$(cd "$(dirname "$0")/.." && pwd)"
scene="$root/examples/pendulum.yaml"
out="$root/out/pendulum"

"$binary" run "$scene" -o "$out"
/usr/bin/python3 "$root/tools/plot_probes.py" "$out/probes.csv" -o "$out/plots" >/dev/null

/usr/bin/python3 - "$out/summary.json" <<'PY'
import json, sys
summary = json.load(open(sys.argv[1]))
x, y, z = summary["probes"]["tip"]["position"]
e = summary["energy"]
print(f"tip at t = {summary['time']:.3g} s: ({x:.4f}, {y:.4f}, {z:.4f}) m;"
      f" energy balance {e['balance']:.3g} J (kinetic {e['kinetic']:.4g} J,"
      f" work of gravity {-e['gravity']:.4g} J)")
PY
cat <<MSG
Results in $out:
  summary.json          final probe values, energies, step and iteration counts
  probes.csv            tip position, mid-point velocity and energies every 0.01 s
  cables.pvd            deformed cable over time: open it in ParaView
  plots/tip_path.png    path of the tip; plots/*.png every probe against time
MSG
