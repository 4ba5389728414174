#!/usr/bin/env python3
"""Plots the probes of an ancfnet run.

Usage: /usr/bin/python3 tools/plot_probes.py PROBES_CSV [-o OUTDIR]

Reads the CSV written by ancfnet (a `time` column, then `NAME.COMPONENT` columns), and writes one
PNG per probe, OUTDIR/NAME.png, with every component of the probe against time. Energy probes also
get the balance kinetic + strain + gravity + dissipated - work, which stays constant in a
consistent run. Position probes also get OUTDIR/NAME_path.png, the path of the point in the plane
of its two widest-ranging coordinates. OUTDIR defaults to the folder of the CSV file. Exit code 2 for a missing or
empty file.
"""

import argparse
import csv
import sys
import warnings
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402 (the backend is chosen first)
import numpy as np  # noqa: E402

# Unit of each column suffix written by ancfnet (analysis/probe.cpp, ProbeColumns).
UNITS = {
    "x": "m", "y": "m", "z": "m",
    "vx": "m/s", "vy": "m/s", "vz": "m/s",
    "kinetic": "J", "strain": "J", "gravity": "J", "work": "J", "dissipated": "J",
    "area": "m²", "distance": "m", "tension": "N", "fx": "N", "fy": "N", "fz": "N", "thread": "index",
}
QUANTITIES = {"m": "position", "m/s": "velocity", "J": "energy", "m²": "area", "N": "force"}
ENERGY_TERMS = ("kinetic", "strain", "gravity", "work", "dissipated")


def read_probes(path, fail):
    """Returns (time, {probe name: {component: values}}) in the order of the columns."""
    if not path.is_file():
        fail(f"{path}: no such file")
    with path.open(newline="") as file:
        header = next(csv.reader(file), None)
    if not header or header[0] != "time" or len(header) < 2:
        fail(f"{path}: empty, or not a probe CSV (expected a header 'time,NAME.COMPONENT,...')")
    try:
        with warnings.catch_warnings():  # a header without rows is reported below, not warned
            warnings.simplefilter("ignore", UserWarning)
            data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    except ValueError as error:
        fail(f"{path}: {error}")
    if data.shape[0] == 0:
        fail(f"{path}: no data rows")
    probes = {}
    for index, column in enumerate(header[1:], start=1):
        name, _, component = column.rpartition(".")
        probes.setdefault(name or column, {})[component] = data[:, index]
    return data[:, 0], probes


def plot_probe(name, time, components, out_dir):
    """Writes OUT_DIR/NAME.png and returns its path."""
    figure, axes = plt.subplots(figsize=(8, 4.5))
    marker = "o" if len(time) == 1 else None
    for component, values in components.items():
        axes.plot(time, values, marker=marker, label=component)
    if all(term in components for term in ENERGY_TERMS):
        c = components
        balance = c["kinetic"] + c["strain"] + c["gravity"] + c["dissipated"] - c["work"]
        axes.plot(time, balance, "k--", marker=marker,
                  label="balance (kinetic+strain+gravity+dissipated-work)")
    units = sorted({UNITS.get(component, "?") for component in components})
    unit = units[0] if len(units) == 1 else ", ".join(units)
    axes.set_xlabel("time [s]")
    axes.set_ylabel(f"{QUANTITIES.get(unit, name)} [{unit}]")
    axes.set_title(name)
    axes.grid(True, alpha=0.3)
    axes.legend(loc="best", fontsize="small")
    figure.tight_layout()
    path = out_dir / f"{name}.png"
    figure.savefig(path, dpi=120)
    plt.close(figure)
    return path


def plot_path(name, components, out_dir):
    """Writes OUT_DIR/NAME_path.png (the point's path, equal axes) and returns its path."""
    ranges = {axis: np.ptp(components[axis]) for axis in "xyz"}
    first, second = sorted(sorted(ranges, key=ranges.get, reverse=True)[:2])
    figure, axes = plt.subplots(figsize=(6, 6))
    axes.plot(components[first], components[second], "-")
    axes.plot(components[first][0], components[second][0], "o", label="start")
    axes.plot(components[first][-1], components[second][-1], "s", label="end")
    axes.set_xlabel(f"{first} [m]")
    axes.set_ylabel(f"{second} [m]")
    axes.set_aspect("equal", adjustable="datalim")
    axes.set_title(f"{name}: path")
    axes.grid(True, alpha=0.3)
    axes.legend(loc="best", fontsize="small")
    figure.tight_layout()
    path = out_dir / f"{name}_path.png"
    figure.savefig(path, dpi=120)
    plt.close(figure)
    return path


def main():
    parser = argparse.ArgumentParser(
        description="Plot the probes of an ancfnet run (one PNG each).")
    parser.add_argument("csv", type=Path, metavar="PROBES_CSV", help="probe CSV written by ancfnet")
    parser.add_argument("-o", "--out-dir", type=Path, metavar="OUTDIR",
                        help="folder for the PNG files (default: the CSV's folder)")
    args = parser.parse_args()

    time, probes = read_probes(args.csv, parser.error)  # parser.error exits with code 2
    out_dir = args.out_dir if args.out_dir is not None else args.csv.resolve().parent
    out_dir.mkdir(parents=True, exist_ok=True)
    for name, components in probes.items():
        print(plot_probe(name, time, components, out_dir))
        if set(components) == set("xyz"):
            print(plot_path(name, components, out_dir))
    return 0


if __name__ == "__main__":
    sys.exit(main())
