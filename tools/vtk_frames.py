"""Reads the frames of a run's cables.pvd: the net's threads and the bodies' axes at each time.

ancfnet writes one ASCII VTK PolyData file per output (io/vtk_writer.hpp): each cable is one
polyline along its centre line, with a `tension` value (N) at each point, and each rigid body
adds its frame after the cables: 4 points (its origin and the tips of its three axes) and three
two-point lines from the origin.
"""

import xml.etree.ElementTree as ElementTree
from dataclasses import dataclass

import numpy as np

from run_folder import RunDataError, check_run_dir


@dataclass
class BodyFrame:
    origin: np.ndarray  # (3,) position of the body's origin (m)
    axis_tips: np.ndarray  # (3, 3) tips of its x, y, z axes (m), one per row


@dataclass
class Frame:
    time: float  # s
    threads: list  # one (n, 3) array of centre-line points (m) per cable
    tensions: list  # one (n,) array of tensions (N) per cable
    bodies: list  # BodyFrame of each rigid body

    def points(self):
        """Every thread point and body point (m), as one (n, 3) array."""
        parts = self.threads + [np.vstack([b.origin, b.axis_tips]) for b in self.bodies]
        return np.vstack(parts) if parts else np.zeros((0, 3))


def read_collection(pvd_path):
    """[(time, path of the frame file)] of a .pvd collection, in the order written."""
    if not pvd_path.is_file():
        raise RunDataError(f"{pvd_path}: no such file (is this the output folder of a run?)")
    try:
        root = ElementTree.parse(pvd_path).getroot()
    except ElementTree.ParseError as error:
        raise RunDataError(f"{pvd_path}: not a VTK collection ({error})") from error
    entries = [(float(d.get("timestep")), pvd_path.parent / d.get("file"))
               for d in root.iter("DataSet")]
    if not entries:
        raise RunDataError(f"{pvd_path}: no frames (the run wrote no output step)")
    return entries


def _array(piece, name, components=1, kind=float):
    for element in piece.iter("DataArray"):
        if element.get("Name") == name:
            values = np.array((element.text or "").split(), dtype=kind)
            return values.reshape(-1, components) if components > 1 else values
    raise RunDataError(f"no DataArray '{name}'")


def _is_body_axis(lines, index):
    """A body's axis: a two-point line sharing its first point with a neighbouring line."""
    line = lines[index]
    neighbours = [lines[j] for j in (index - 1, index + 1) if 0 <= j < len(lines)]
    return len(line) == 2 and any(len(n) == 2 and n[0] == line[0] for n in neighbours)


def read_frame(time, path):
    """The Frame stored in one .vtp file of the series."""
    try:
        piece = next(ElementTree.parse(path).getroot().iter("Piece"))
        points = _array(piece, "position", 3) if int(piece.get("NumberOfPoints")) else None
        if points is None:
            return Frame(time, [], [], [])
        tension = _array(piece, "tension")
        connectivity = _array(piece, "connectivity", kind=np.int64)
        offsets = _array(piece, "offsets", kind=np.int64)
    except (OSError, ElementTree.ParseError, StopIteration, RunDataError, ValueError) as error:
        raise RunDataError(f"{path}: not a readable ancfnet VTK frame ({error})") from error
    lines = np.split(connectivity, offsets[:-1])
    frame = Frame(time, [], [], [])
    axes = []
    for index, line in enumerate(lines):
        if _is_body_axis(lines, index):
            axes.append(line)
            if len(axes) == 3:
                frame.bodies.append(BodyFrame(points[axes[0][0]], points[[a[1] for a in axes]]))
                axes = []
        else:
            frame.threads.append(points[line])
            frame.tensions.append(tension[line])
    return frame


def read_frames(run_dir, times=None):
    """The Frames of RUN_DIR/cables.pvd: all of them, or those nearest each of `times` (s)."""
    entries = read_collection(check_run_dir(run_dir) / "cables.pvd")
    if times is not None:
        stored = np.array([t for t, _ in entries])
        entries = [entries[int(np.argmin(np.abs(stored - t)))] for t in times]
    return [read_frame(t, path) for t, path in entries]
