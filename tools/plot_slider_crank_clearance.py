#!/usr/bin/env python3
"""Plots a slider-crank with a revolute clearance joint: the slider's acceleration against the
ideal mechanism's, and the journal's orbit inside the clearance circle.

Usage: /usr/bin/python3 tools/plot_slider_crank_clearance.py PROBES_CSV --crank R --rod L
       --rate OMEGA --clearance C [--slider slider] [--joint pin] [-o OUTDIR]

PROBES_CSV is the probe file of an ancfnet run of a crank of length R (m) turning at the constant
rate OMEGA (rad/s) from θ = 0 at t = 0, a rod of length L and a slider on the x axis
(examples/slider_crank_clearance.yaml): a `body_velocity` probe of the slider (NAME.vx) and a
`clearance_joint` probe of the joint (NAME.ex, NAME.ey). The slider's acceleration is the
central difference of its velocity; the ideal one is the exact kinematics of the rigid mechanism,
x = R cos θ + √(L² − R² sin² θ), differentiated twice at constant ω (Flores & Ambrósio 2004):
  ẍ = −R ω² cos θ − R² ω² [cos 2θ / S + R² sin² θ cos² θ / S³],  S = √(L² − R² sin² θ).
Writes OUTDIR/slider_acceleration.png and OUTDIR/journal_orbit.png (OUTDIR: the folder of the CSV
unless -o is given) and prints their paths and the rms accelerations; exit code 2 for bad input.
"""

import argparse
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402 (the backend is chosen first)
import numpy as np  # noqa: E402

from probe_csv import read_probes  # noqa: E402


def ideal_slider_acceleration(theta, crank, rod, rate):
    """ẍ of the ideal slider-crank at crank angle θ turning at the constant rate ω."""
    s = np.sqrt(rod * rod - (crank * np.sin(theta)) ** 2)
    sin_cos = np.sin(theta) * np.cos(theta)
    return -crank * rate**2 * np.cos(theta) - (crank * rate) ** 2 * (
        np.cos(2 * theta) / s + crank**2 * sin_cos**2 / s**3
    )


def probe_components(probes, name, components, csv, fail):
    probe = probes.get(name)
    if probe is None or any(c not in probe for c in components):
        wanted = ", ".join(f"{name}.{c}" for c in components)
        fail(f"{csv}: no columns {wanted} (probes: {', '.join(probes)})")
    return [probe[c] for c in components]


def plot_acceleration(time, measured, ideal, output):
    figure, axes = plt.subplots(figsize=(8, 4.5))
    axes.plot(time * 1e3, measured, lw=0.8, label="clearance joint (ancfnet)")
    axes.plot(time * 1e3, ideal, "--", lw=1.2, label="ideal joints (exact kinematics)")
    axes.set_xlabel("time [ms]")
    axes.set_ylabel("slider acceleration [m/s²]")
    axes.set_title("Slider acceleration, revolute clearance at the piston pin")
    axes.grid(True, alpha=0.3)
    axes.legend(loc="best", fontsize="small")
    figure.tight_layout()
    figure.savefig(output, dpi=120)
    plt.close(figure)


def plot_orbit(ex, ey, clearance, output):
    figure, axes = plt.subplots(figsize=(5.5, 6.2))
    angle = np.linspace(0.0, 2.0 * np.pi, 361)
    scale = 1e3  # mm
    axes.plot(scale * clearance * np.cos(angle), scale * clearance * np.sin(angle), "k-", lw=1.0,
              label=f"clearance circle, c = {scale * clearance:g} mm")
    axes.plot(scale * ex, scale * ey, lw=0.7, label="journal centre relative to the bearing")
    axes.set_aspect("equal")
    axes.set_xlabel("eccentricity x [mm]")
    axes.set_ylabel("eccentricity y [mm]")
    axes.set_title("Journal orbit")
    axes.grid(True, alpha=0.3)
    axes.legend(loc="upper center", bbox_to_anchor=(0.5, -0.12), fontsize="small")
    figure.tight_layout()
    figure.savefig(output, dpi=120)
    plt.close(figure)


def main():
    parser = argparse.ArgumentParser(description="Plot a slider-crank with a clearance joint.")
    parser.add_argument("csv", type=Path, metavar="PROBES_CSV")
    parser.add_argument("--crank", type=float, required=True, help="crank length R (m)")
    parser.add_argument("--rod", type=float, required=True, help="rod length L (m)")
    parser.add_argument("--rate", type=float, required=True, help="crank rate ω (rad/s)")
    parser.add_argument("--clearance", type=float, required=True, help="radial clearance c (m)")
    parser.add_argument("--slider", default="slider", help="the slider's body_velocity probe")
    parser.add_argument("--joint", default="pin", help="the clearance_joint probe")
    parser.add_argument("-o", "--output", type=Path, metavar="OUTDIR")
    args = parser.parse_args()
    if not (args.crank > 0 and args.rod > args.crank and args.clearance > 0):
        parser.error("need 0 < --crank < --rod and --clearance > 0")

    time, probes = read_probes(args.csv, parser.error)
    if time.size < 3:
        parser.error(f"{args.csv}: fewer than three rows, no acceleration to difference")
    (vx,) = probe_components(probes, args.slider, ["vx"], args.csv, parser.error)
    ex, ey = probe_components(probes, args.joint, ["ex", "ey"], args.csv, parser.error)
    measured = np.gradient(vx, time)
    ideal = ideal_slider_acceleration(args.rate * time, args.crank, args.rod, args.rate)

    out_dir = args.output or args.csv.resolve().parent
    out_dir.mkdir(parents=True, exist_ok=True)
    acceleration_png = out_dir / "slider_acceleration.png"
    orbit_png = out_dir / "journal_orbit.png"
    plot_acceleration(time, measured, ideal, acceleration_png)
    plot_orbit(ex, ey, args.clearance, orbit_png)
    print(acceleration_png)
    print(orbit_png)
    rms = lambda values: float(np.sqrt(np.mean(values**2)))  # noqa: E731
    print(f"rms slider acceleration {rms(measured):.6g} m/s² (ideal {rms(ideal):.6g})")
    print(f"largest eccentricity {np.max(np.hypot(ex, ey)):.4g} m (clearance {args.clearance:g})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
