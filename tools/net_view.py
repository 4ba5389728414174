"""Draws a Frame (vtk_frames.py) of the net and the bodies on matplotlib 3D axes."""

import numpy as np
from matplotlib.ticker import MaxNLocator
from mpl_toolkits.mplot3d.art3d import Line3DCollection

# Name of each view: (elevation, azimuth) of the camera in degrees (matplotlib's view_init), and
# the axis it looks along (its ticks are hidden), if any.
VIEWS = {
    "front": (0, -90, "y"),  # looking along +y: the x-z plane
    "side": (0, 0, "x"),  # looking along -x: the y-z plane
    "top": (90, -90, "z"),  # looking down -z: the x-y plane
    "oblique": (25, -60, None),
}
THREAD_COLOR = "tab:blue"
TARGET_COLORS = ("0.35", "tab:brown", "tab:purple", "tab:olive")
AXIS_COLORS = ("tab:red", "tab:green", "k")


def bounding_cube(frames, outlines=()):
    """(centre, half side) of a cube holding every point of every frame and of the targets'
    outlines (target_shapes.py) in them (m), with a margin."""
    parts = [f.points() for f in frames]
    parts += [o.in_world(f).reshape(-1, 3) for f in frames for o in outlines]
    points = np.vstack([p for p in parts if len(p)] or [np.zeros((1, 3))])
    low, high = points.min(axis=0), points.max(axis=0)
    half = max(0.5 * float(np.max(high - low)), 1e-3) * 1.05
    return 0.5 * (low + high), half


def prepare_axes(axes, cube, view):
    """Equal scales on x, y, z over `cube`, metres on every axis, the camera of VIEWS[view]."""
    centre, half = cube
    axes.set_xlim(centre[0] - half, centre[0] + half)
    axes.set_ylim(centre[1] - half, centre[1] + half)
    axes.set_zlim(centre[2] - half, centre[2] + half)
    axes.set_box_aspect((1, 1, 1))
    elevation, azimuth, edge_on = VIEWS[view]
    for name, axis in zip("xyz", (axes.xaxis, axes.yaxis, axes.zaxis)):
        if name == edge_on:
            axis.set_ticks([])
        else:
            axis.set_label_text(f"{name} [m]")
            axis.set_major_locator(MaxNLocator(5))
    axes.view_init(elevation, azimuth)
    axes.tick_params(labelsize="x-small")


def draw_frame(axes, frame, outlines=(), label=True):
    """Adds the threads, the body axes and the targets' `outlines` (target_shapes.py) of
    `frame`; returns the artists added."""
    threads = Line3DCollection(frame.threads, colors=THREAD_COLOR, linewidths=0.8,
                               label="cables (net threads, tethers)" if label else None)
    axes.add_collection3d(threads)
    artists = [threads]
    for number, body in enumerate(frame.bodies):
        for tip, color, name in zip(body.axis_tips, AXIS_COLORS, "xyz"):
            segment = np.vstack([body.origin, tip])
            text = f"body {name} axis" if label and number == 0 else None
            artists += axes.plot(*segment.T, color=color, linewidth=2.0, label=text)
    for index, outline in enumerate(outlines):
        color = TARGET_COLORS[index % len(TARGET_COLORS)]
        target = Line3DCollection(outline.in_world(frame), colors=color, linewidths=0.6,
                                  label=f"target {outline.name}" if label else None)
        axes.add_collection3d(target)
        artists.append(target)
    return artists
