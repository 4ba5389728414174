#!/usr/bin/env bash
# The README's demo: runs the main example (a tether net shot at a tumbling, box-shaped target
# that carries a mesh antenna, in zero gravity, with self-contact), plots its probes, draws the
# one-page capture report and the movie (docs/plots.md) and says where everything is. The net
# deployment stays an example (examples/net_deploy.yaml).
# Usage: scripts/run-demo.sh <ancfnet binary>   (called by `make demo` after the build)
set -euo pipefail

binary="${1:?usage: run-demo.sh <ancfnet binary>}"
root="$(cd "$(dirname "$0")/.." && pwd)"
scene="$root/examples/net_capture.yaml"
out="$root/out/net_capture"

"$binary" run "$scene" -o "$out"
/usr/bin/python3 "$root/tools/plot_probes.py" "$out/probes.csv" -o "$out/plots" >/dev/null
"$binary" report "$out" --scene "$scene" >/dev/null
"$binary" animate "$out" --scene "$scene" >/dev/null

/usr/bin/python3 - "$out/summary.json" <<'PY'
import json, sys
summary = json.load(open(sys.argv[1]))
probes = summary["probes"]
hull, antenna = probes["hull"]["contact"], probes["antenna"]["contact"]
rates = probes["rates"]["body_velocity"]
print(f"at t = {summary['time']:.3g} s: {hull['active']} contacts on the hull "
      f"({hull['normal_force']:.3g} N), {antenna['active']} on the antenna "
      f"({antenna['normal_force']:.3g} N); target drifting at "
      f"{[round(v, 4) for v in rates['linear']]} m/s; "
      f"{summary['steps']} steps, {summary['wall_time_s']:.1f} s")
PY
cat <<MSG
Results in $out:
  summary.json              final probe values, energies, step and iteration counts
  probes.csv                target pose and rates, contact forces and moments on the hull and the
                            antenna, net centroid, energies every 0.01 s
  cables.pvd                the net and the target's axes over time: open it in ParaView
  contacts.pvd              the contact points and forces, beside cables.pvd
  plots/*.png               every probe against time, one panel per quantity
  report.png                the capture on one page: the net from three views at three times,
                            energy balance, contact forces, thread tension, target rates
  animation.mp4 (or .gif)   the net and the target moving (ancfnet animate; .gif without ffmpeg)
MSG
