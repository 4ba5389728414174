#!/usr/bin/env python3
"""An animation of a run's net and bodies, for people without ParaView.

Usage: /usr/bin/python3 tools/animate_run.py RUN_DIR [-o FILE] [--fps N] [--every K]
       [--view front|side|top|oblique] [--scene SCENE]   (or `ancfnet animate RUN_DIR ...`)

Reads the frames of RUN_DIR/cables.pvd (the net's threads and the bodies' axes at each output)
and writes one movie frame per K-th output, the camera fixed and the scales equal and fixed over
the whole run; with --scene, the outlines of the scene's contact targets move with their bodies
(target_shapes.py). FILE's suffix picks the format: .mp4 through Debian's ffmpeg (matplotlib's
FFMpegWriter), .gif through Pillow (matplotlib's PillowWriter). The default is RUN_DIR/animation.mp4
when ffmpeg is installed, else RUN_DIR/animation.gif. Exit code 2 for a missing run folder, a
missing or empty cables.pvd, or an .mp4 without ffmpeg.
"""

import argparse
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402 (the backend is chosen first)
from matplotlib import animation  # noqa: E402

from net_view import VIEWS, bounding_cube, draw_frame, prepare_axes  # noqa: E402
from run_folder import RunDataError, exit_on_run_data_error, warn  # noqa: E402
from target_shapes import read_target_outlines  # noqa: E402
from vtk_frames import read_frames  # noqa: E402


def has_ffmpeg():
    return animation.writers.is_available("ffmpeg")


def movie_writer(output, fps):
    """The matplotlib writer for `output`'s suffix; RunDataError when it cannot be written."""
    suffix = output.suffix.lower()
    if suffix == ".gif":
        return animation.PillowWriter(fps=fps)
    if suffix == ".mp4":
        if not has_ffmpeg():
            raise RunDataError(f"{output}: writing MP4 needs ffmpeg (Debian package ffmpeg: "
                               "scripts/install-deps.sh --video), or ask for a .gif")
        return animation.FFMpegWriter(fps=fps)
    raise RunDataError(f"{output}: unknown movie format '{suffix}' (use .mp4 or .gif)")


def make_animation(frames, view="oblique", fps=10, outlines=()):
    """(figure, FuncAnimation) showing `frames` one after the other, with the targets'
    `outlines` (target_shapes.py)."""
    figure = plt.figure(figsize=(7, 7))
    axes = figure.add_subplot(projection="3d")
    cube = bounding_cube(frames, outlines)

    def show(index):
        axes.clear()
        prepare_axes(axes, cube, view)
        artists = draw_frame(axes, frames[index], outlines)
        axes.set_title(f"t = {frames[index].time:.4g} s ({view} view)")
        axes.legend(loc="upper left", fontsize="x-small")
        return artists

    movie = animation.FuncAnimation(figure, show, frames=len(frames), interval=1000 / fps,
                                    blit=False)
    return figure, movie


def main():
    parser = argparse.ArgumentParser(
        prog="animate_run.py", description="Animate the net and bodies of an ancfnet run.")
    parser.add_argument("run_dir", type=Path, metavar="RUN_DIR", help="output folder of a run")
    parser.add_argument("-o", "--output", type=Path, metavar="FILE",
                        help="the movie, .mp4 (ffmpeg) or .gif (default: RUN_DIR/animation.mp4, "
                             "or .gif without ffmpeg)")
    parser.add_argument("--fps", type=float, default=10.0, help="frames per second (default 10)")
    parser.add_argument("--every", type=int, default=1, metavar="K",
                        help="one movie frame per K outputs (default 1)")
    parser.add_argument("--view", choices=sorted(VIEWS), default="oblique",
                        help="camera (default oblique)")
    parser.add_argument("--scene", type=Path, metavar="SCENE",
                        help="the run's scene file: draw its contact targets")
    args = parser.parse_args()
    if args.every < 1 or args.fps <= 0:
        parser.error("--every must be ≥ 1 and --fps > 0")

    def run():
        frames = read_frames(args.run_dir)[::args.every]
        default = "animation.mp4" if has_ffmpeg() else "animation.gif"
        output = args.output or args.run_dir / default
        writer = movie_writer(output, args.fps)
        output.parent.mkdir(parents=True, exist_ok=True)
        outlines = read_target_outlines(args.scene, warn) if args.scene else ()
        figure, movie = make_animation(frames, args.view, args.fps, outlines)
        movie.save(output, writer=writer, dpi=100)
        plt.close(figure)
        print(f"{output}: {len(frames)} frames")
        return 0

    return exit_on_run_data_error(parser.prog, run)


if __name__ == "__main__":
    sys.exit(main())
