#!/usr/bin/env python3
"""Plots the probes of an ancfnet run.

Usage: /usr/bin/python3 tools/plot_probes.py PROBES_CSV [-o OUTDIR]

Reads the CSV written by ancfnet (a `time` column, then `NAME.COMPONENT` columns), and writes one
PNG per probe, OUTDIR/NAME.png, with one panel per physical quantity (a contact probe: the number
of contacts, its forces in N, its moments in N m and its penetration in m, each on its own axis
with its SI unit), every curve named in the legend (probe_quantities.py). Energy probes also get
the balance kinetic + strain + gravity + dissipated - work, which stays constant in a consistent
run. Position probes also get OUTDIR/NAME_path.png, the path of the point in the plane of its two
widest-ranging coordinates. OUTDIR defaults to the folder of the CSV file. Exit code 2 for a
missing or empty file.
"""

import argparse
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402 (the backend is chosen first)
import numpy as np  # noqa: E402
from matplotlib.ticker import MaxNLocator  # noqa: E402

from probe_csv import read_probes  # noqa: E402
from probe_quantities import COUNTS, XYZ, probe_panels  # noqa: E402

PANEL_HEIGHT_IN = 2.4


def draw_panel(axes, time, panel):
    """Draws one Panel against time on `axes`: its curves, its SI unit, its legend."""
    marker = "o" if len(time) == 1 else None
    for curve in panel.curves:
        style = "k--" if curve.label.startswith("balance") else "-"
        axes.plot(time, curve.values, style, marker=marker, label=curve.label)
    axes.set_ylabel(panel.ylabel)
    if panel.quantity in COUNTS:
        axes.yaxis.set_major_locator(MaxNLocator(integer=True))
    axes.grid(True, alpha=0.3)
    axes.legend(loc="best", fontsize="x-small")


def make_probe_figure(name, time, components):
    """The figure of one probe: a column of panels sharing the time axis."""
    panels = probe_panels(name, components)
    figure, axes = plt.subplots(len(panels), 1, sharex=True, squeeze=False,
                                figsize=(8, 1.2 + PANEL_HEIGHT_IN * len(panels)))
    for row, panel in zip(axes[:, 0], panels):
        draw_panel(row, time, panel)
    axes[-1, 0].set_xlabel("time [s]")
    axes[0, 0].set_title(f"probe {name}")
    figure.tight_layout()
    return figure


def make_path_figure(name, components):
    """The point's path in the plane of its two widest-ranging coordinates (equal axes)."""
    ranges = {axis: np.ptp(components[axis]) for axis in XYZ}
    first, second = sorted(sorted(ranges, key=ranges.get, reverse=True)[:2])
    figure, axes = plt.subplots(figsize=(6, 6))
    axes.plot(components[first], components[second], "-", label=f"path of {name}")
    axes.plot(components[first][0], components[second][0], "o", label="start")
    axes.plot(components[first][-1], components[second][-1], "s", label="end")
    axes.set_xlabel(f"{first} [m]")
    axes.set_ylabel(f"{second} [m]")
    axes.set_aspect("equal", adjustable="datalim")
    axes.set_title(f"{name}: path")
    axes.grid(True, alpha=0.3)
    axes.legend(loc="best", fontsize="small")
    figure.tight_layout()
    return figure


def save(figure, path):
    figure.savefig(path, dpi=120)
    plt.close(figure)
    return path


def main():
    parser = argparse.ArgumentParser(
        description="Plot the probes of an ancfnet run (one PNG each, one panel per quantity).")
    parser.add_argument("csv", type=Path, metavar="PROBES_CSV", help="probe CSV written by ancfnet")
    parser.add_argument("-o", "--out-dir", type=Path, metavar="OUTDIR",
                        help="folder for the PNG files (default: the CSV's folder)")
    args = parser.parse_args()

    time, probes = read_probes(args.csv, parser.error)  # parser.error exits with code 2
    out_dir = args.out_dir if args.out_dir is not None else args.csv.resolve().parent
    out_dir.mkdir(parents=True, exist_ok=True)
    for name, components in probes.items():
        print(save(make_probe_figure(name, time, components), out_dir / f"{name}.png"))
        if set(components) == set(XYZ):
            print(save(make_path_figure(name, components), out_dir / f"{name}_path.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
