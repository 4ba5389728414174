#!/usr/bin/env python3
"""Plots the deployment of a net: mouth area and distance travelled against time.

Usage: /usr/bin/python3 tools/plot_deployment.py PROBES_CSV [--area NAME] [--distance NAME]
       [-o PNG]

Reads the probe CSV of an ancfnet run with a `mouth_area` probe (column NAME.area, default
`mouth`) and a `distance` probe (NAME.distance, default `travel`), and writes one PNG (default:
deployment.png beside the CSV) with the area on the left axis, the distance on the right one, and
the peak area marked. Prints the path and the peak. Exit code 2 for a missing file or column.
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
    figure, left = plt.subplots(figsize=(8, 4.5))
    left.plot(time, area, color="tab:blue", label="mouth area")
    left.plot(time[peak], area[peak], "o", color="tab:blue")
    left.annotate(f"peak {area[peak]:.3g} m² at {time[peak]:.3g} s", (time[peak], area[peak]),
                  textcoords="offset points", xytext=(8, -14), fontsize="small")
    left.set_xlabel("time [s]")
    left.set_ylabel("mouth area [m²]", color="tab:blue")
    left.grid(True, alpha=0.3)
    right = left.twinx()
    right.plot(time, distance, color="tab:orange", label="distance travelled")
    right.set_ylabel("centroid distance along the axis [m]", color="tab:orange")
    left.set_title("Net deployment")
    figure.legend(loc="upper left", bbox_to_anchor=(0.1, 0.9), fontsize="small")
    figure.tight_layout()
    figure.savefig(output, dpi=120)
    plt.close(figure)
    print(output)
    print(f"peak mouth area {area[peak]:.4g} m² at t = {time[peak]:.4g} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
