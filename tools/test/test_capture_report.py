"""capture_report.py and `ancfnet report`: the panels of the page, their units and legends."""

import pytest

from capture_report import SNAPSHOT_VIEWS, make_report
from run_folder import RunDataError
from vtk_frames import read_frames

TIME_PANELS = {  # title: (y label, a curve it must name)
    "energy balance": ("energy [J]", "kinetic energy"),
    "contact forces": ("force [N]", "normal force on hull (Σ F_n)"),
    "tether tension": ("tension [N]", "largest thread tension (threads)"),
    "target rates": ("angular velocity [rad/s]", "angular velocity about body x (rates)"),
}

# The axis labels of each view: the axis it looks along is hidden.
VISIBLE_AXES = {"front": ["x [m]", "", "z [m]"], "side": ["", "y [m]", "z [m]"],
                "top": ["x [m]", "y [m]", ""]}


def snapshot_axes(figure):
    return [a for a in figure.axes if a.name == "3d"]


def time_axes(figure):
    return {a.get_title(): a for a in figure.axes if a.name != "3d"}


def legend_texts(axes):
    return [text.get_text() for text in axes.get_legend().get_texts()]


def test_report_has_three_views_at_each_chosen_time(capture_run):
    figure = make_report(capture_run, [0.0, 0.031, 0.06])
    titles = [a.get_title() for a in snapshot_axes(figure)]
    assert titles == [f"{view} view, t = {t} s" for t in ("0", "0.03", "0.06")
                      for view in SNAPSHOT_VIEWS]
    threads = len(read_frames(capture_run, [0.0])[0].threads)
    figure.canvas.draw()  # projects the 3D lines
    for axes in snapshot_axes(figure):
        view = axes.get_title().split()[0]
        labels = [axes.get_xlabel(), axes.get_ylabel(), axes.get_zlabel()]
        assert labels == VISIBLE_AXES[view]
        assert len(axes.collections[0].get_segments()) == threads


def test_report_time_panels_have_units_and_named_curves(capture_run):
    panels = time_axes(make_report(capture_run))
    assert set(panels) == set(TIME_PANELS)
    for title, (ylabel, curve) in TIME_PANELS.items():
        assert panels[title].get_ylabel() == ylabel
        assert panels[title].get_xlabel() == "time [s]"
        assert curve in legend_texts(panels[title]), title


def test_tension_comes_from_the_frames_without_a_tension_probe(run_copy):
    probes_csv = run_copy / "probes.csv"
    rows = [line.split(",") for line in probes_csv.read_text().splitlines()]
    keep = [i for i, name in enumerate(rows[0]) if not name.startswith("threads.")]
    probes_csv.write_text("\n".join(",".join(row[i] for i in keep) for row in rows) + "\n")
    tension = time_axes(make_report(run_copy))["tether tension"]
    assert legend_texts(tension) == ["largest thread tension, all cables (VTK frames)"]
    frames = read_frames(run_copy)
    (line,) = tension.get_lines()
    assert list(line.get_xdata()) == [f.time for f in frames]
    assert max(line.get_ydata()) > 0.0


def test_a_time_outside_the_run_is_refused(capture_run):
    with pytest.raises(RunDataError, match="outside the run's outputs"):
        make_report(capture_run, [1.0])


def test_cli_writes_png_and_pdf(cli, capture_run, tmp_path):
    output = tmp_path / "page.png"
    finished = cli("report", capture_run, "--times", "0.02", "0.04", "-o", output, "--pdf")
    assert finished.returncode == 0, finished.stderr
    assert output.stat().st_size > 0 and output.with_suffix(".pdf").stat().st_size > 0


# Both commands that read a run folder (report, and animate) refuse one without a run.
@pytest.mark.parametrize("command", ["report", "animate"])
@pytest.mark.parametrize("subfolder, message", [("missing", "no such folder"),
                                                ("empty", "no run data")])
def test_cli_refuses_a_folder_without_a_run(cli, tmp_path, command, subfolder, message):
    (tmp_path / "empty").mkdir()
    finished = cli(command, tmp_path / subfolder)
    assert finished.returncode == 2
    assert message in finished.stderr


def test_cli_refuses_a_time_outside_the_run(cli, capture_run):
    finished = cli("report", capture_run, "--times", "5")
    assert finished.returncode == 2
    assert "--times 5 s is outside the run's outputs (0 s to 0.06 s)" in finished.stderr
