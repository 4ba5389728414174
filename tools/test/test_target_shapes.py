"""target_shapes.py: the outlines of the contact targets, placed by their body's pose."""

from pathlib import Path

import numpy as np

from capture_report import make_report
from target_shapes import read_target_outlines
from vtk_frames import read_frames

SCENE = Path(__file__).with_name("small_capture.yaml")
EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_box_on_a_body_turns_with_it(capture_run):
    (hull,) = read_target_outlines(SCENE)
    assert (hull.name, hull.body, hull.segments.shape) == ("hull", 0, (12, 2, 3))
    first, last = read_frames(capture_run, [0.0, 0.06])
    corners = hull.in_world(first).reshape(-1, 3)
    np.testing.assert_allclose(corners.min(axis=0), [-0.15] * 3, atol=1e-12)
    np.testing.assert_allclose(corners.max(axis=0), [0.15] * 3, atol=1e-12)
    moved = hull.in_world(last).reshape(-1, 3) - last.bodies[0].origin
    np.testing.assert_allclose(np.linalg.norm(moved, axis=1), np.sqrt(3) * 0.15, rtol=1e-9)
    assert not np.allclose(moved, corners)  # the target tumbles


def test_mesh_and_sphere_outlines_and_a_note_for_a_plane(tmp_path):
    scene = tmp_path / "scene.yaml"
    scene.write_text(f"""
contact:
  targets:
    - {{name: ground, type: plane, point: [0, 0, 0], normal: [0, 0, 1]}}
    - {{name: ball, type: sphere, center: [0, 0, 1], radius: 0.5}}
    - {{name: dish, type: mesh, file: {EXAMPLES / 'data' / 'antenna_dish.obj'},
       position: [0, 0, 2]}}
""")
    notes = []
    ball, dish = read_target_outlines(scene, notes.append)
    assert notes == ["target 'ground' (plane) is not drawn: only boxes, spheres, cylinders, "
                     "capsules and OBJ meshes are"]
    assert ball.body == dish.body == -1
    distances = np.linalg.norm(ball.segments.reshape(-1, 3) - [0, 0, 1], axis=1)
    np.testing.assert_allclose(distances, 0.5)
    assert dish.segments[:, :, 2].min() >= 2.0 - 1e-12 and len(dish.segments) > 100


def test_report_and_animation_draw_the_target(cli, capture_run, tmp_path):
    for command, output, *more in (("report", "page.png"),
                                   ("animate", "movie.gif", "--every", "4")):
        finished = cli(command, capture_run, "--scene", SCENE, "-o", tmp_path / output, *more)
        assert finished.returncode == 0, finished.stderr
        assert (tmp_path / output).stat().st_size > 0


def test_report_legend_names_the_target(capture_run):
    figure = make_report(capture_run, None, read_target_outlines(SCENE))
    legend = [t.get_text() for t in figure.axes[0].get_legend().get_texts()]
    assert legend == ["cables (net threads, tethers)", "body x axis", "body y axis",
                      "body z axis", "target hull"]


def test_a_scene_that_is_not_yaml_is_refused(cli, capture_run, tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("contact: [unclosed\n")
    finished = cli("report", capture_run, "--scene", bad)
    assert finished.returncode == 2
    assert "cannot read the scene" in finished.stderr
