#!/usr/bin/env python3
"""A one-page report of a capture run: snapshots of the net, energy, contact, tension, rates.

Usage: /usr/bin/python3 tools/capture_report.py RUN_DIR [--times T ...] [--scene SCENE]
       [-o FILE] [--pdf]                      (or `ancfnet report RUN_DIR ...`)

Reads the output folder of `ancfnet run` (probes.csv and the frames of cables.pvd) and writes one
page (default RUN_DIR/report.png; --pdf adds the same page as a PDF beside it):
  - the net and the bodies' axes at three chosen times (--times, default the first, middle and
    last output; each time is taken from the nearest output), each seen from the front (x-z),
    the side (y-z) and the top (x-y), on equal scales; with --scene, the outlines of the scene's
    contact targets too (target_shapes.py);
  - the energy balance (energy probe: each term and kinetic + strain + gravity + dissipated -
    work), in J;
  - the contact forces (Σ F_n of each contact probe), in N;
  - the tether tension (max_tension and link_force probes; without them, the largest tension
    over every thread in the VTK frames), in N;
  - the target's rates (angular velocity of each body_velocity probe, body axes), in rad/s.
A panel whose probe the scene lacks says so. Exit code 2 for a missing run folder, missing or
empty probes.csv or cables.pvd, or a time outside the run.
"""

import argparse
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402 (the backend is chosen first)
import numpy as np  # noqa: E402

from net_view import bounding_cube, draw_frame, prepare_axes  # noqa: E402
from plot_probes import draw_panel  # noqa: E402
from probe_quantities import Curve, Panel, describe, probe_kind, probe_panels  # noqa: E402
from run_folder import RunDataError, exit_on_run_data_error, read_run_probes, warn  # noqa: E402
from target_shapes import read_target_outlines  # noqa: E402
from vtk_frames import read_collection, read_frames  # noqa: E402

SNAPSHOT_VIEWS = ("front", "side", "top")
PAGE_SIZE_IN = (12, 17)  # width, height: the proportions of A4


def chosen_times(stored, times):
    """The output times to show: `times` (s), or the first, middle and last output."""
    if not times:
        return [stored[0], stored[len(stored) // 2], stored[-1]]
    tolerance = 1e-9 * max(1.0, abs(stored[-1]))
    for t in times:
        if not stored[0] - tolerance <= t <= stored[-1] + tolerance:
            raise RunDataError(f"--times {t:g} s is outside the run's outputs "
                               f"({stored[0]:g} s to {stored[-1]:g} s)")
    return times


def probe_curves(probes, kind, components, quantity, unit):
    """A Panel with the columns `components` of every probe of `kind`."""
    panel = Panel(quantity, unit)
    for name, columns in probes.items():
        if probe_kind(columns) == kind:
            for component in components:
                panel.curves.append(Curve(describe(name, component, kind)[2], columns[component]))
    return panel


def energy_panel(probes):
    for name, columns in probes.items():
        if probe_kind(columns) == "energy":
            return probe_panels(name, columns)[0]
    return Panel("energy", "J")


def tension_panel(probes, run_dir):
    """Tensions of the max_tension and link_force probes, else the largest in the frames."""
    panel = probe_curves(probes, "max_tension", ["tension"], "tension", "N")
    panel.curves += probe_curves(probes, "link_force", ["tension"], "tension", "N").curves
    if panel.curves:
        return panel, None
    frames = read_frames(run_dir)
    largest = [max((float(np.max(t)) for t in f.tensions if len(t)), default=0.0) for f in frames]
    panel.curves.append(Curve("largest thread tension, all cables (VTK frames)",
                              np.array(largest)))
    return panel, np.array([f.time for f in frames])


def draw_time_panel(axes, time, panel, missing):
    """draw_panel, or the panel's axis labels and a note when it has no curve."""
    axes.set_xlabel("time [s]")
    if panel.curves:
        draw_panel(axes, time, panel)
        return
    axes.set_ylabel(panel.ylabel)
    axes.text(0.5, 0.5, missing, ha="center", va="center", transform=axes.transAxes)


def make_report(run_dir, times=None, outlines=()):
    """The report's Figure for the run in `run_dir` at the output times nearest `times`, the
    targets' `outlines` (target_shapes.py) drawn in the snapshots."""
    run_dir = Path(run_dir)
    time, probes = read_run_probes(run_dir)
    stored = [t for t, _ in read_collection(run_dir / "cables.pvd")]
    frames = read_frames(run_dir, chosen_times(stored, times))
    figure = plt.figure(figsize=PAGE_SIZE_IN, layout="constrained")
    grid = figure.add_gridspec(len(frames) + 2, len(SNAPSHOT_VIEWS),
                               height_ratios=[1.0] * len(frames) + [0.8, 0.8])
    cube = bounding_cube(frames, outlines)
    for row, frame in enumerate(frames):
        for column, view in enumerate(SNAPSHOT_VIEWS):
            axes = figure.add_subplot(grid[row, column], projection="3d")
            prepare_axes(axes, cube, view)
            draw_frame(axes, frame, outlines, label=(row, column) == (0, 0))
            axes.set_title(f"{view} view, t = {frame.time:.4g} s", fontsize="small")
            if (row, column) == (0, 0):
                axes.legend(loc="upper left", fontsize="x-small")

    plots = grid[len(frames):, :].subgridspec(2, 2)
    tension, tension_time = tension_panel(probes, run_dir)
    panels = [
        (energy_panel(probes), time, "energy balance", "no energy probe"),
        (probe_curves(probes, "contact", ["normal_force"], "force", "N"), time,
         "contact forces", "no contact probe"),
        (tension, time if tension_time is None else tension_time, "tether tension", ""),
        (probe_curves(probes, "body_velocity", ["wx", "wy", "wz"], "angular velocity",
                      "rad/s"), time, "target rates", "no body_velocity probe"),
    ]
    for index, (panel, panel_time, title, missing) in enumerate(panels):
        axes = figure.add_subplot(plots[index // 2, index % 2])
        draw_time_panel(axes, panel_time, panel, missing)
        axes.set_title(title)
    figure.suptitle(f"Capture report: {run_dir.resolve().name} "
                    f"(t = {time[0]:.4g} s to {time[-1]:.4g} s)")
    return figure


def main():
    parser = argparse.ArgumentParser(
        prog="capture_report.py", description="One-page report of an ancfnet capture run.")
    parser.add_argument("run_dir", type=Path, metavar="RUN_DIR", help="output folder of a run")
    parser.add_argument("--times", type=float, nargs="+", metavar="T",
                        help="times of the snapshots, s (default: first, middle, last output)")
    parser.add_argument("--scene", type=Path, metavar="SCENE",
                        help="the run's scene file: draw its contact targets in the snapshots")
    parser.add_argument("-o", "--output", type=Path, metavar="FILE",
                        help="the page, PNG or PDF by its suffix (default: RUN_DIR/report.png)")
    parser.add_argument("--pdf", action="store_true", help="also write the page as a PDF")
    args = parser.parse_args()

    def run():
        outlines = read_target_outlines(args.scene, warn) if args.scene else ()
        figure = make_report(args.run_dir, args.times, outlines)
        output = args.output or args.run_dir / "report.png"
        outputs = [output] + ([output.with_suffix(".pdf")] if args.pdf else [])
        for path in dict.fromkeys(outputs):
            path.parent.mkdir(parents=True, exist_ok=True)
            figure.savefig(path, dpi=100)
            print(path)
        plt.close(figure)
        return 0

    return exit_on_run_data_error(parser.prog, run)


if __name__ == "__main__":
    sys.exit(main())
