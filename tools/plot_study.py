#!/usr/bin/env python3
"""Plots the success envelope of an ancfnet study: a metric over two varied parameters.

Usage: /usr/bin/python3 tools/plot_study.py STUDY_CSV --x PARAMETER --y PARAMETER
       --metric COLUMN [-o PNG]

Reads the table of `ancfnet study` (docs/studies.md: a `case` column, one column per varied
parameter, `status`, `reason`, then the metrics of each case's summary.json) and draws one point
per case at (x, y), coloured by the metric (e.g. `grab.enclosed_fraction`, the capture quality),
with a colour bar naming it; failed cases are grey crosses. A grid of at least 2 × 2 values is
also shaded between its points. Writes PNG (default: study.png beside the table). Exit code 2
for a missing table or a column it lacks.
"""

import argparse
import csv
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402 (the backend is chosen first)
import numpy as np  # noqa: E402


def read_table(path):
    """The rows of the study table as dictionaries; exits with 2 when it cannot be read."""
    try:
        with open(path, newline="") as file:
            rows = list(csv.DictReader(file))
    except OSError as error:
        print(f"plot_study.py: {path}: {error.strerror}", file=sys.stderr)
        sys.exit(2)
    if not rows:
        print(f"plot_study.py: {path}: no cases", file=sys.stderr)
        sys.exit(2)
    return rows


def column(rows, name, path):
    """The values of column `name` as floats (NaN for empty cells)."""
    if name not in rows[0]:
        print(f"plot_study.py: {path}: no column '{name}'; columns: {', '.join(rows[0])}",
              file=sys.stderr)
        sys.exit(2)
    return np.array([float(row[name]) if row[name] != "" else np.nan for row in rows])


def padded_range(values):
    """The range of the finite `values` widened by 8 % on each side (by 1 when they are equal)."""
    low, high = np.nanmin(values), np.nanmax(values)
    pad = 0.08 * (high - low) if high > low else 1.0
    return low - pad, high + pad


def make_figure(rows, x_name, y_name, metric_name, path):
    """The figure: the metric over (x, y), failed cases marked."""
    x = column(rows, x_name, path)
    y = column(rows, y_name, path)
    metric = column(rows, metric_name, path)
    ok = np.array([row["status"] == "ok" for row in rows]) & np.isfinite(metric)
    figure, axes = plt.subplots(figsize=(7, 5.5))
    if ok.sum() >= 4 and len(np.unique(x[ok])) >= 2 and len(np.unique(y[ok])) >= 2:
        try:
            shading = axes.tricontourf(x[ok], y[ok], metric[ok], levels=12, alpha=0.35)
            shading.set_clim(np.nanmin(metric[ok]), np.nanmax(metric[ok]))
        except (ValueError, RuntimeError):  # points on a line: no triangles to shade
            pass
    points = axes.scatter(x[ok], y[ok], c=metric[ok], s=60, edgecolors="k", zorder=3)
    if (~ok).any():
        axes.scatter(x[~ok], y[~ok], marker="x", c="0.5", s=60, zorder=3, label="failed case")
        axes.legend(loc="best", fontsize="small")
    axes.set_xlim(*padded_range(x))  # the points on the range's edges drawn whole
    axes.set_ylim(*padded_range(y))
    figure.colorbar(points, ax=axes, label=metric_name)
    axes.set_xlabel(x_name)
    axes.set_ylabel(y_name)
    axes.set_title(f"{metric_name} over {len(rows)} cases")
    axes.grid(True, alpha=0.3)
    figure.tight_layout()
    return figure


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("table", type=Path, help="study.csv of `ancfnet study`")
    parser.add_argument("--x", required=True, help="parameter on the horizontal axis")
    parser.add_argument("--y", required=True, help="parameter on the vertical axis")
    parser.add_argument("--metric", required=True, help="column drawn as colour")
    parser.add_argument("-o", "--output", type=Path, help="PNG file (default: study.png)")
    args = parser.parse_args()
    rows = read_table(args.table)
    figure = make_figure(rows, args.x, args.y, args.metric, args.table)
    output = args.output or args.table.with_name("study.png")
    figure.savefig(output, dpi=110)
    print(f"plot_study.py: wrote {output}")


if __name__ == "__main__":
    main()
