"""ancfnet.ModelBuilder builds the model of a scene file in code: the same run, bit for bit, and
the builder's and the scene readers' messages for bad input."""

import json

import pytest

import ancfnet
from scenes import ROOT, short_scene

# Timings differ from run to run, and the source names the scene file or the builder.
DIFFERENT = ("wall_time_s", "output_time_s")


def output_files(directory):
    """Every output file of a run but summary.json, by name, as bytes."""
    return {p.name: p.read_bytes() for p in sorted(directory.iterdir()) if p.name != "summary.json"}


def pendulum_builder():
    """The model of examples/pendulum.yaml: a 1.2 m cable of 8 elements pinned at its start."""
    builder = ancfnet.ModelBuilder()
    builder.set_gravity([0, 0, -9.81])
    soft = ancfnet.Material(youngs_modulus=0.7e6, density=5540)
    strip = ancfnet.Section.rectangle(width=0.2, height=0.009)
    builder.add_cable("pendulum", [0, 0, 0], [1.2, 0, 0], 8, soft, strip)
    builder.add_pin("pendulum", 0.0)
    return builder


PENDULUM_SETTINGS = {
    "analysis": {"type": "dynamic", "integrator": "generalized_alpha", "spectral_radius": 0.8,
                 "time_step": 1.0e-3, "end_time": 0.1},
    "output": {"interval": 1.0e-2, "vtk_points_per_element": 8},
    "probes": [{"name": "tip", "quantity": "position", "at": "pendulum.end"},
               {"name": "middle", "quantity": "velocity", "at": {"cable": "pendulum", "s": 0.5}},
               {"name": "energy", "quantity": "energy"}],
}


def test_a_built_pendulum_runs_as_its_scene_file_bit_for_bit(tmp_path):
    from_file = ancfnet.run(ancfnet.parse_scene(short_scene("pendulum", 0.1)), tmp_path / "yaml")
    scene = pendulum_builder().build_scene(PENDULUM_SETTINGS)
    assert scene.probe_columns[:4] == ["time", "tip.x", "tip.y", "tip.z"]

    built = ancfnet.run(scene, tmp_path / "built")

    assert built["status"] == "completed" and built["steps"] == 100
    assert output_files(tmp_path / "built") == output_files(tmp_path / "yaml")
    assert ({k: v for k, v in built.items() if k not in DIFFERENT} ==
            {k: v for k, v in from_file.items() if k not in DIFFERENT})


def test_a_built_static_cantilever_runs_as_its_scene_file_bit_for_bit(tmp_path):
    from_file = ancfnet.run(ancfnet.load_scene(ROOT / "examples" / "cantilever_static.yaml"),
                            tmp_path / "yaml")
    builder = ancfnet.ModelBuilder()
    builder.set_gravity([0, 0, 0])
    steel = ancfnet.Material(youngs_modulus=2.0e11, density=7800)
    bar = ancfnet.Section.rectangle(0.01, 0.01)
    builder.add_cable("beam", [0, 0, 0], [1, 0, 0], 16, steel, bar)
    builder.add_clamp("beam", 0.0)
    builder.add_point_force("beam", 1.0, [0, 0, -333.333])
    scene = builder.build_scene({
        "probes": [{"name": "tip", "quantity": "position", "at": "beam.end"}],
        "analysis": {"type": "static", "load_steps": 10}})
    assert scene.analysis == "static"

    built = ancfnet.run(scene, tmp_path / "built")

    assert built["status"] == "completed"
    assert output_files(tmp_path / "built") == output_files(tmp_path / "yaml")
    assert built["probes"]["tip"] == from_file["probes"]["tip"]


BODY_AND_MASS = """
gravity: [0, 0, -9.81]
materials:
  steel: {youngs_modulus: 2.0e11, density: 7800}
sections:
  rod: {shape: circle, diameter: 0.01}
point_masses:
  - {name: ball, mass: 0.5, position: [0, 1, 0], velocity: [1, 0, 2]}
  - {name: post, mass: 1.0, position: [0, 2, 0], fixed: true}
cables:
  - {name: rod, start: [0, 0, 0], end: [0.5, 0, 0], elements: 4, material: steel, section: rod}
bodies:
  - {name: box, mass: 3.0, inertia: [0.1, 0.2, 0.25], position: [2, 0, 0],
     velocity: [0, 1, 0], angular_velocity: [0.5, 0, 2]}
constraints:
  - {type: clamp, at: rod.start}
analysis: {type: dynamic, time_step: 1.0e-3, end_time: 0.05}
output: {interval: 0.01}
probes:
  - {name: ball, quantity: position, at: ball}
  - {name: box, quantity: body_pose, body: box}
"""


def test_built_masses_and_bodies_step_as_their_scene_file(tmp_path):
    """A free and a fixed point mass, a clamped rod and a tumbling body under gravity: the
    states at each output step of Simulation are those of the same scene file."""
    builder = ancfnet.ModelBuilder()
    builder.set_gravity([0, 0, -9.81])
    builder.add_point_mass("ball", 0.5, [0, 1, 0], velocity=[1, 0, 2])
    builder.add_point_mass("post", 1.0, [0, 2, 0])
    builder.fix_point_mass("post")
    builder.add_cable("rod", [0, 0, 0], [0.5, 0, 0], 4, ancfnet.Material(2.0e11, 7800),
                      ancfnet.Section.circle(0.01))
    builder.add_rigid_body("box", 3.0, [0.1, 0.2, 0.25], [2, 0, 0], velocity=[0, 1, 0],
                           angular_velocity=[0.5, 0, 2])
    builder.add_clamp("rod", 0.0)
    scene = builder.build_scene({
        "analysis": {"type": "dynamic", "time_step": 1.0e-3, "end_time": 0.05},
        "output": {"interval": 0.01},
        "probes": [{"name": "ball", "quantity": "position", "at": "ball"},
                   {"name": "box", "quantity": "body_pose", "body": "box"}]})
    built = ancfnet.Simulation(scene, tmp_path / "built")
    from_file = ancfnet.Simulation(ancfnet.parse_scene(BODY_AND_MASS), tmp_path / "yaml")
    steps = 0
    while built.advance():
        assert from_file.advance()
        assert built.t == from_file.t
        assert list(built.q) == list(from_file.q) and list(built.v) == list(from_file.v)
        steps += 1
    assert steps == 6 and not from_file.advance()
    assert output_files(tmp_path / "built") == output_files(tmp_path / "yaml")


NET = """
gravity: [0, 0, -9.81]
materials:
  thread: {youngs_modulus: 1.0e9, density: 1000, axial_damping_time: 1.0e-4}
sections:
  thread: {shape: circle, diameter: 0.002}
nets:
  - {name: net, type: square, side: 1.0, meshes: 4, center: [0, 0, 1], material: thread,
     section: thread, elements_per_thread: 2, knot_mass: 0.01, velocity: [0.5, 0, 2]}
constraints:
  - {type: pin, at: net.t0.start}
probes:
  - {name: mouth, quantity: mouth_area, net: net}
  - {name: middle, quantity: centroid, net: net}
analysis: {type: dynamic, time_step: 1.0e-3, end_time: 0.02}
output: {interval: 0.005}
"""


def test_a_built_net_runs_as_its_scene_file_bit_for_bit(tmp_path):
    """A square net thrown up and pinned at a corner."""
    builder = ancfnet.ModelBuilder()
    builder.set_gravity([0, 0, -9.81])
    builder.add_square_net("net", 1.0, 4, [0, 0, 1], ancfnet.Material(1.0e9, 1000, 1.0e-4),
                           ancfnet.Section.circle(0.002), elements_per_thread=2,
                           knot_mass=0.01, velocity=[0.5, 0, 2])
    builder.add_pin("net.t0", 0.0)
    scene = builder.build_scene({
        "probes": [{"name": "mouth", "quantity": "mouth_area", "net": "net"},
                   {"name": "middle", "quantity": "centroid", "net": "net"}],
        "analysis": {"type": "dynamic", "time_step": 1.0e-3, "end_time": 0.02},
        "output": {"interval": 0.005}})

    built = ancfnet.run(scene, tmp_path / "built")
    from_file = ancfnet.run(ancfnet.parse_scene(NET), tmp_path / "yaml")

    assert built["status"] == "completed"
    assert output_files(tmp_path / "built") == output_files(tmp_path / "yaml")
    assert built["probes"] == from_file["probes"]


CAPTURE = """
gravity: [0, 0, -9.81]
materials:
  thread: {youngs_modulus: 1.0e9, density: 1000, axial_damping_time: 1.0e-4}
sections:
  thread: {shape: circle, diameter: 0.002}
nets:
  - {name: net, type: square, side: 1.0, meshes: 4, center: [0, 0, 0.33], material: thread,
     section: thread, knot_mass: 0.01, velocity: [0, 0, -1]}
contact:
  law: {type: carvalho_martins, stiffness: 1.0e6, restitution: 0.3}
  friction: {type: tanh, static: 0.3, kinetic: 0.3, regularization_speed: 1.0e-2}
  targets:
    - {name: ball, type: sphere, center: [0, 0, 0], radius: 0.3}
probes:
  - {name: grab, quantity: capture, net: net, target: ball}
  - {name: ball, quantity: contact, target: ball}
analysis: {type: dynamic, time_step: 1.0e-3, end_time: 0.05}
output: {interval: 0.01}
"""


def capture_builder():
    builder = ancfnet.ModelBuilder()
    builder.set_gravity([0, 0, -9.81])
    builder.add_square_net("net", 1.0, 4, [0, 0, 0.33], ancfnet.Material(1.0e9, 1000, 1.0e-4),
                           ancfnet.Section.circle(0.002), knot_mass=0.01, velocity=[0, 0, -1])
    return builder


def test_a_built_net_with_contact_runs_as_its_scene_file_bit_for_bit(tmp_path):
    """A net thrown onto a ball, with friction and a capture probe: set_contact."""
    builder = capture_builder()
    builder.set_contact({
        "law": {"type": "carvalho_martins", "stiffness": 1.0e6, "restitution": 0.3},
        "friction": {"type": "tanh", "static": 0.3, "kinetic": 0.3,
                     "regularization_speed": 1.0e-2},
        "targets": [{"name": "ball", "type": "sphere", "center": [0, 0, 0], "radius": 0.3}]})
    scene = builder.build_scene({
        "probes": [{"name": "grab", "quantity": "capture", "net": "net", "target": "ball"},
                   {"name": "ball", "quantity": "contact", "target": "ball"}],
        "analysis": {"type": "dynamic", "time_step": 1.0e-3, "end_time": 0.05},
        "output": {"interval": 0.01}})

    built = ancfnet.run(scene, tmp_path / "built")
    from_file = ancfnet.run(ancfnet.parse_scene(CAPTURE), tmp_path / "yaml")

    assert built["status"] == "completed"
    # The net reaches the ball (3 cm below it at 1 m/s) within the run.
    assert built["probes"]["grab"]["capture"]["first_contact_time"] is not None
    assert output_files(tmp_path / "built") == output_files(tmp_path / "yaml")
    assert built["probes"] == from_file["probes"]


def test_bad_contact_raises_the_scene_files_message():
    builder = capture_builder()
    with pytest.raises(ancfnet.InputError) as error:
        builder.set_contact({"law": {"type": "hertz", "stiffness": 1.0e6},
                             "targets": [{"name": "ball", "type": "sphere", "center": [0, 0, 0],
                                          "radius": -0.3}]},
                            source_name="contact")
    assert str(error.value).startswith("contact:1:")
    assert "(key 'radius')" in str(error.value)
    with pytest.raises(ancfnet.InputError, match="missing required key 'law'"):
        builder.set_contact({"targets": []})


def test_bad_input_raises_the_builders_message():
    builder = ancfnet.ModelBuilder()
    with pytest.raises(ancfnet.InputError, match=r"^youngs_modulus must be > 0 \(got -1"):
        ancfnet.Material(youngs_modulus=-1.0, density=1000)
    with pytest.raises(ancfnet.InputError, match=r"^diameter must be > 0 \(got 0"):
        ancfnet.Section.circle(0.0)
    steel = ancfnet.Material(2.1e11, 7800)
    rod = ancfnet.Section.circle(0.01)
    with pytest.raises(ancfnet.InputError, match=r"at least 1 element \(got 0\)"):
        builder.add_cable("rod", [0, 0, 0], [1, 0, 0], 0, steel, rod)
    with pytest.raises(ancfnet.InputError, match="zero length"):
        builder.add_cable("rod", [0, 0, 0], [0, 0, 0], 2, steel, rod)
    builder.add_cable("rod", [0, 0, 0], [1, 0, 0], 2, steel, rod)
    with pytest.raises(ancfnet.InputError, match="'rod'"):
        builder.add_cable("rod", [0, 0, 0], [1, 0, 0], 2, steel, rod)
    with pytest.raises(ancfnet.InputError, match="body mass must be > 0"):
        builder.add_rigid_body("box", -3.0, [1, 1, 1], [0, 0, 0])
    with pytest.raises(ancfnet.InputError, match=r"at least 1 mesh per side \(got 0 × 0\)"):
        builder.add_square_net("net", 1.0, 0, [0, 0, 0], steel, rod)


def test_bad_settings_raise_the_scene_files_message():
    builder = pendulum_builder()
    settings = json.loads(json.dumps(PENDULUM_SETTINGS))
    settings["analysis"]["time_step"] = -1e-3
    with pytest.raises(ancfnet.InputError) as error:
        builder.build_scene(settings, "pendulum")
    assert str(error.value).startswith("pendulum:1:")
    assert str(error.value).endswith("(key 'time_step')")

    settings = json.loads(json.dumps(PENDULUM_SETTINGS))
    settings["probes"][0]["at"] = "pendulm.end"
    with pytest.raises(ancfnet.InputError, match="pendulm"):
        builder.build_scene(settings)

    with pytest.raises(ancfnet.InputError, match="unknown key 'analysys'"):
        builder.build_scene({"analysys": {}})
    with pytest.raises(ancfnet.InputError, match="no cable"):
        ancfnet.ModelBuilder().build_scene()
