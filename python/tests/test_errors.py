"""Invalid input raises ancfnet.InputError (a ValueError) with the command-line tool's message:
file, line, column and key."""

import pytest

import ancfnet

BAD_KEY = """\
gravity: [0, 0, -9.81]
materials:
  steel: {youngs_modulus: 2.1e11, density: 7800, poisons_ratio: 0.3}
"""


def test_input_error_is_a_value_error():
    assert issubclass(ancfnet.InputError, ValueError)
    assert issubclass(ancfnet.SolverError, RuntimeError)


def test_a_bad_key_names_source_line_and_key():
    with pytest.raises(ancfnet.InputError) as error:
        ancfnet.parse_scene(BAD_KEY, "bad.yaml")
    message = str(error.value)
    assert message.startswith("bad.yaml:3:50: unknown key 'poisons_ratio'")


def test_the_message_is_the_clis(tmp_path, cli, pendulum_text):
    scene_file = tmp_path / "bad.yaml"
    scene_file.write_text(pendulum_text.replace("elements: 8", "elements: -8"))
    process = cli("run", scene_file, "-o", tmp_path / "out", "-q")
    assert process.returncode == 2

    with pytest.raises(ancfnet.InputError) as error:
        ancfnet.load_scene(scene_file)

    assert process.stderr == f"ancfnet: {error.value}\n"
    assert str(error.value).startswith(f"{scene_file}:15:15: ")
    assert str(error.value).endswith("(key 'elements')")


def test_a_missing_file():
    with pytest.raises(ancfnet.InputError, match="missing.yaml: cannot open scene file"):
        ancfnet.load_scene("missing.yaml")


def test_a_malformed_probe_file(tmp_path):
    bad = tmp_path / "probes.csv"
    bad.write_text("t,x\n0,1\n")
    with pytest.raises(ancfnet.InputError, match="probes.csv"):
        ancfnet.read_probes(bad)
