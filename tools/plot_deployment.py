#!/usr/bin/env python3
"""Plots the deployment of a net: mouth area and distance travelled against time.

Usage: /usr/bin/python3 tools/plot_deployment.py PROBES_CSV [--area NAME] [--distance NAME]
       [-o PNG]

Reads the probe CSV of an ancfnet run with a `mouth_area` probe (column NAME.area, default
`mouth`) and a `distance` probe (NAME.distance, default `travel`), and writes one PNG (default:
deployment.png beside the CSV) with two panels sharing the time axis, the area (peak marked) and
the distance. Prints the path and the peak. Exit code 2 for a missing file or column.
"""

import argparse
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402 (the backend is chosen first)
import numpy as np  # noqa: E402

from probe_csv import read_probes  # noqa: E402


def column(probes, name, component, fail):
    if name not in probes or component not in probes[name]:
        fail(f"no column {name}.{component} in the CSV (probes: {', '.join(probes)})")
    return probes[name][component]


def main():
    parser = argparse.ArgumentParser(description="Plot a net's mouth area and travel.")
    parser.add_argument("csv", type=Path, metavar="PROBES_CSV")
    parser.add_argument("--area", default="mouth", help="name of the mouth_area probe")
    parser.add_argument("--distance", default="travel", help="name of the distance probe")
    parser.add_argument("-o", "--output", type=Path, metavar="PNG")
    args = parser.parse_args()

    time, probes = read_probes(args.csv, parser.error)
    area = column(probes, args.area, "area", parser.error)
    distance = column(probes, args.distance, "distance", parser.error)
    output = args.output or args.csv.resolve().parent / "deployment.png"
    output.parent.mkdir(parents=True, exist_ok=True)

    peak = int(np.argmax(area))
    figure, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(8, 6))
    top.plot(time, area, label=f"mouth area ({args.area})")
    top.plot(time[peak], area[peak], "o", color="tab:blue", label="peak")
    top.annotate(f"peak {area[peak]:.3g} m² at {time[peak]:.3g} s", (time[peak], area[peak]),
                 textcoords="offset points", xytext=(8, -14), fontsize="small")
    top.set_ylabel("mouth area [m²]")
    top.set_title("Net deployment")
    bottom.plot(time, distance, color="tab:orange",
                label=f"centroid distance along the launch axis ({args.distance})")
    bottom.set_ylabel("distance [m]")
    bottom.set_xlabel("time [s]")
    for axes, place in ((top, "center left"), (bottom, "upper left")):
        axes.grid(True, alpha=0.3)
        axes.legend(loc=place, fontsize="small")
    figure.tight_layout()
    figure.savefig(output, dpi=120)
    plt.close(figure)
    print(output)
    print(f"peak mouth area {area[peak]:.4g} m² at t = {time[peak]:.4g} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
