#!/usr/bin/env bash
# The README's demo: runs the main example (the deployment of a square tether net pulled open by
# four corner bullets), plots its probes and says where everything is.
# Usage: scripts/run-demo.sh <ancfnet binary>   (called by `make demo` after the build)
set -euo pipefail

binary="${1:?usage: run-demo.sh <ancfnet binary>}"
root="$(cd "$(dirname "$0")/.." && pwd)"
scene="$root/examples/net_deploy.yaml"
out="$root/out/net_deploy"

"$binary" run "$scene" -o "$out"
/usr/bin/python3 "$root/tools/plot_probes.py" "$out/probes.csv" -o "$out/plots" >/dev/null
/usr/bin/python3 "$root/tools/plot_deployment.py" "$out/probes.csv" -o "$out/plots/deployment.png" |
  tail -n 1

/usr/bin/python3 - "$out/summary.json" <<'PY'
import json, sys
summary = json.load(open(sys.argv[1]))
probes = summary["probes"]
tension = probes["tension"]["max_tension"]
print(f"at t = {summary['time']:.3g} s: centroid {probes['travel']['distance']:.3f} m along the axis,"
      f" largest thread tension {tension['tension']:.3g} N in {tension['thread']};"
      f" {summary['steps']} steps, {summary['wall_time_s']:.2f} s")
PY
cat <<MSG
Results in $out:
  summary.json              final probe values, energies, step and iteration counts
  probes.csv                mouth area, travel, centroid, bullet, tension, energies every 0.01 s
  cables.pvd                the net over time (threads coloured by tension): open it in ParaView
  plots/deployment.png      mouth area and distance travelled; plots/*.png every probe
MSG
