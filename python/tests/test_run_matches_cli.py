"""ancfnet.run and ancfnet.Simulation make the very run of `ancfnet run`: the same files, bit for
bit, on the same scene."""

import json

import pytest

import ancfnet
from scenes import short_scene

# Timings differ from run to run; every other key of summary.json must match.
TIMINGS = ("wall_time_s", "output_time_s")


def output_files(directory):
    """Every output file of a run but summary.json, by name, as bytes."""
    return {p.name: p.read_bytes() for p in sorted(directory.iterdir()) if p.name != "summary.json"}


def summary_without_timings(summary):
    return {key: value for key, value in summary.items() if key not in TIMINGS}


@pytest.mark.parametrize("name, end_time", [("pendulum", 0.1), ("cantilever_static", None)])
def test_run_writes_the_files_of_the_cli_bit_for_bit(tmp_path, cli, name, end_time):
    scene_file = tmp_path / f"{name}.yaml"
    scene_file.write_text(short_scene(name, end_time))
    process = cli("run", scene_file, "-o", tmp_path / "cli", "-q")
    assert process.returncode == 0, process.stderr

    summary = ancfnet.run(ancfnet.load_scene(scene_file), tmp_path / "api")

    assert summary["status"] == "completed"
    cli_files = output_files(tmp_path / "cli")
    assert "probes.csv" in cli_files and "cables.pvd" in cli_files
    assert output_files(tmp_path / "api") == cli_files
    cli_summary = json.loads((tmp_path / "cli" / "summary.json").read_text())
    assert summary_without_timings(summary) == summary_without_timings(cli_summary)


def test_stepping_equals_running(tmp_path, pendulum_text):
    scene = ancfnet.parse_scene(pendulum_text)
    summary = ancfnet.run(scene, tmp_path / "run")

    simulation = ancfnet.Simulation(scene, tmp_path / "stepped")
    times = []
    while simulation.advance():
        times.append(simulation.t)

    assert simulation.finished
    probes = ancfnet.read_probes(tmp_path / "run" / "probes.csv")
    assert times == list(probes["time"])
    assert output_files(tmp_path / "stepped") == output_files(tmp_path / "run")
    assert summary_without_timings(simulation.summary) == summary_without_timings(summary)


def test_the_state_is_the_one_the_probes_record(tmp_path, pendulum_text):
    scene = ancfnet.parse_scene(pendulum_text)
    simulation = ancfnet.Simulation(scene, tmp_path)
    tips = []
    while simulation.advance():
        tips.append(simulation.q[-6:-3].copy())  # the last node's position: the tip

    probes = ancfnet.read_probes(tmp_path / "probes.csv")
    for row, tip in enumerate(tips):
        assert list(tip) == [probes[f"tip.{axis}"][row] for axis in "xyz"]


def test_run_to_end_after_some_steps(tmp_path, pendulum_text):
    scene = ancfnet.parse_scene(pendulum_text)
    reference = ancfnet.run(scene, tmp_path / "run")
    simulation = ancfnet.Simulation(scene, tmp_path / "stepped")
    for _ in range(3):
        assert simulation.advance()
    summary = simulation.run_to_end()
    assert summary_without_timings(summary) == summary_without_timings(reference)
    assert not simulation.advance()


def test_dropping_a_simulation_abandons_its_run(tmp_path, pendulum_text):
    simulation = ancfnet.Simulation(ancfnet.parse_scene(pendulum_text), tmp_path)
    assert simulation.advance() and simulation.advance()
    del simulation

    assert len(ancfnet.read_probes(tmp_path / "probes.csv")["time"]) == 2
    assert not (tmp_path / "summary.json").exists()
