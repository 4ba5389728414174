#!/usr/bin/env python3
"""Plots the tip deflection of a spin-up in the hub's rotating frame.

Usage: /usr/bin/python3 tools/plot_spin_up.py PROBES_CSV --rate OMEGA --time T
       [--probe tip] [--assumed-modes AMM_CSV] [-o PNG]

PROBES_CSV is the probe file of an ancfnet run of a beam clamped to a hub turning about z by the
spin-up θ(t) = (Ω/T)[t²/2 + (T/2π)²(cos(2πt/T) − 1)] (then Ω (t − T/2)); the position probe
`tip` (NAME.x, NAME.y) is turned into the rotating frame: v = −x sin θ + y cos θ. AMM_CSV, from
`ancfnet assumed-modes -o AMM_CSV`, adds the linear assumed-modes model (clipped to the plot when
it diverges). Writes spin_up.png beside the CSV unless -o is given; exit code 2 for bad input.
"""

import argparse
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402 (the backend is chosen first)
import numpy as np  # noqa: E402

from probe_csv import read_probes  # noqa: E402


def hub_angle(t, rate, ramp):
    w = 2 * np.pi / ramp
    spin = (rate / ramp) * (0.5 * t * t + (np.cos(w * t) - 1) / (w * w))
    return np.where(t <= ramp, spin, rate * (t - 0.5 * ramp))


def main():
    parser = argparse.ArgumentParser(description="Plot a spin-up's tip deflection.")
    parser.add_argument("csv", type=Path, metavar="PROBES_CSV")
    parser.add_argument("--rate", type=float, required=True, help="final hub rate Ω (rad/s)")
    parser.add_argument("--time", type=float, required=True, help="spin-up time T (s)")
    parser.add_argument("--probe", default="tip", help="name of the tip position probe")
    parser.add_argument("--assumed-modes", type=Path, metavar="AMM_CSV")
    parser.add_argument("-o", "--output", type=Path, metavar="PNG")
    args = parser.parse_args()
    if not args.time > 0:
        parser.error("--time must be > 0")

    time, probes = read_probes(args.csv, parser.error)
    tip = probes.get(args.probe)
    if tip is None or "x" not in tip or "y" not in tip:
        parser.error(f"no position probe '{args.probe}' in {args.csv} "
                     f"(probes: {', '.join(probes)})")
    theta = hub_angle(time, args.rate, args.time)
    deflection = -tip["x"] * np.sin(theta) + tip["y"] * np.cos(theta)

    figure, axes = plt.subplots(figsize=(8, 4.5))
    axes.plot(time, deflection, label="ANCF (absolute coordinates)")
    limit = 1.5 * np.max(np.abs(deflection))
    if args.assumed_modes:
        if not args.assumed_modes.is_file():
            parser.error(f"{args.assumed_modes}: no such file")
        amm = np.loadtxt(args.assumed_modes, delimiter=",", skiprows=1, ndmin=2)
        axes.plot(amm[:, 0], amm[:, 1], "--", label="assumed modes, linear (no stiffening)")
        axes.set_ylim(-limit, limit)
    axes.set_xlabel("time [s]")
    axes.set_ylabel("tip deflection in the rotating frame [m]")
    axes.set_title(f"Spin-up to {args.rate:g} rad/s in {args.time:g} s")
    axes.grid(True, alpha=0.3)
    axes.legend(loc="best", fontsize="small")
    figure.tight_layout()
    output = args.output or args.csv.resolve().parent / "spin_up.png"
    output.parent.mkdir(parents=True, exist_ok=True)
    figure.savefig(output, dpi=120)
    plt.close(figure)
    print(output)
    print(f"largest tip deflection {np.max(np.abs(deflection)):.4g} m")
    return 0


if __name__ == "__main__":
    sys.exit(main())
