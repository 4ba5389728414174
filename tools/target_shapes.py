"""Outlines of a scene's contact targets, to draw the target with the net (--scene of the report
and the animation).

Reads only the `bodies` names and the `contact.targets` of the scene file (docs/scene-format.md,
"contact") with Debian's python3-yaml: the scene loader stays the C++ one, and a scene it
refuses may still draw here. Boxes, spheres, cylinders, capsules and OBJ meshes become line
segments in the frame of their body (or of the world); each frame of the run (vtk_frames.py)
gives the body's pose. Planes and meshes in other formats are left out, with a note.
"""

from dataclasses import dataclass
from pathlib import Path

import numpy as np
import yaml

from run_folder import RunDataError

CIRCLE_POINTS = 25


@dataclass
class TargetOutline:
    name: str
    body: int  # index of its body in the scene's `bodies` (and in each Frame), -1 for the world
    segments: np.ndarray  # (n, 2, 3): line segments in the body's frame (m)

    def in_world(self, frame):
        """The segments placed by the pose of the body in `frame` (a vtk_frames.Frame)."""
        if self.body < 0:
            return self.segments
        body = frame.bodies[self.body]
        axes = body.axis_tips - body.origin
        rotation = (axes / np.linalg.norm(axes, axis=1)[:, None]).T  # columns: body axes
        return self.segments @ rotation.T + body.origin


def _circle(centre, normal, radius):
    """Segments of the circle of `radius` about `centre` in the plane normal to `normal`."""
    normal = np.asarray(normal, float) / np.linalg.norm(normal)
    helper = np.eye(3)[np.argmin(np.abs(normal))]
    u = np.cross(normal, helper)
    u /= np.linalg.norm(u)
    v = np.cross(normal, u)
    angle = np.linspace(0.0, 2.0 * np.pi, CIRCLE_POINTS)
    points = centre + radius * (np.outer(np.cos(angle), u) + np.outer(np.sin(angle), v))
    return np.stack([points[:-1], points[1:]], axis=1)


def _box(target):
    centre, half = np.array(target["center"], float), np.array(target["half_extents"], float)
    corners = np.array([[i, j, k] for i in (-1, 1) for j in (-1, 1) for k in (-1, 1)])
    edges = [(a, b) for a in range(8) for b in range(a + 1, 8)
             if np.count_nonzero(corners[a] != corners[b]) == 1]
    return np.array([[centre + half * corners[a], centre + half * corners[b]] for a, b in edges])


def _sphere(target):
    centre, radius = np.array(target["center"], float), float(target["radius"])
    return np.concatenate([_circle(centre, axis, radius) for axis in np.eye(3)])


def _cylinder(target):
    centre, radius = np.array(target["center"], float), float(target["radius"])
    axis = np.array(target.get("axis", [0, 0, 1]), float)
    axis /= np.linalg.norm(axis)
    ends = [centre + s * float(target["half_length"]) * axis for s in (-1, 1)]
    rims = [_circle(end, axis, radius) for end in ends]
    sides = np.stack([rims[0][::6, 0], rims[1][::6, 0]], axis=1)
    return np.concatenate(rims + [sides])


def _rotation(rotation):
    """R of a mesh's `rotation: {angle (degrees), axis}` (Rodrigues)."""
    if not rotation:
        return np.eye(3)
    axis = np.array(rotation.get("axis", [0, 0, 1]), float)
    axis /= np.linalg.norm(axis)
    angle = np.radians(float(rotation["angle"]))
    cross = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(angle) * cross + (1 - np.cos(angle)) * cross @ cross


def _obj_mesh(target, scene_dir):
    path = Path(target["file"])
    path = path if path.is_absolute() else scene_dir / path
    if path.suffix.lower() != ".obj" or not path.is_file():
        return None
    vertices, edges = [], set()
    for line in path.read_text().splitlines():
        words = line.split()
        if words and words[0] == "v":
            vertices.append([float(w) for w in words[1:4]])
        elif words and words[0] == "f":
            corners = [int(w.split("/")[0]) - 1 for w in words[1:]]
            edges.update(tuple(sorted(e)) for e in zip(corners, corners[1:] + corners[:1]))
    placed = (float(target.get("scale", 1.0)) * np.array(vertices)) @ _rotation(
        target.get("rotation")).T + np.array(target.get("position", [0, 0, 0]), float)
    return np.array([[placed[a], placed[b]] for a, b in sorted(edges)])


OUTLINES = {"box": _box, "sphere": _sphere, "cylinder": _cylinder, "capsule": _cylinder}


def read_target_outlines(scene_path, warn=print):
    """The TargetOutlines of the scene's contact targets; `warn(message)` for those left out."""
    scene_path = Path(scene_path)
    try:
        scene = yaml.safe_load(scene_path.read_text()) or {}
    except (OSError, yaml.YAMLError) as error:
        raise RunDataError(f"{scene_path}: cannot read the scene ({error})") from error
    bodies = [body.get("name") for body in scene.get("bodies") or []]
    outlines = []
    for target in (scene.get("contact") or {}).get("targets") or []:
        kind, name = target.get("type"), target.get("name", "?")
        try:
            segments = (_obj_mesh(target, scene_path.parent) if kind == "mesh"
                        else OUTLINES[kind](target) if kind in OUTLINES else None)
        except (KeyError, TypeError, ValueError) as error:
            raise RunDataError(f"{scene_path}: target '{name}': {error!r}") from error
        if segments is None:
            warn(f"target '{name}' ({kind}) is not drawn: only boxes, spheres, cylinders, "
                 "capsules and OBJ meshes are")
            continue
        body = bodies.index(target["body"]) if target.get("body") in bodies else -1
        outlines.append(TargetOutline(name, body, segments))
    return outlines
