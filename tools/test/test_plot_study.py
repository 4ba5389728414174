"""plot_study.py: the metric over two parameters, failed cases marked, missing columns refused."""

import subprocess
import sys
from pathlib import Path

import pytest

from plot_study import make_figure, read_table

SCRIPT = Path(__file__).resolve().parents[1] / "plot_study.py"
TABLE = ('case,speed,spin,status,reason,grab.enclosed_fraction\n'
         '0,-4,0,ok,"",0.5\n1,-4,1,ok,"",0.7\n2,-6,0,failed,"solver gave up",\n'
         '3,-6,1,ok,"",0.9\n4,-8,0,ok,"",0.1\n')


@pytest.fixture()
def table(tmp_path):
    path = tmp_path / "study.csv"
    path.write_text(TABLE)
    return path


def test_points_are_coloured_by_the_metric_and_failed_cases_crossed(table):
    figure = make_figure(read_table(table), "speed", "spin", "grab.enclosed_fraction", table)
    axes = figure.axes[0]
    assert axes.get_xlabel() == "speed" and axes.get_ylabel() == "spin"
    assert figure.axes[1].get_ylabel() == "grab.enclosed_fraction"  # the colour bar
    assert [t.get_text() for t in axes.get_legend().get_texts()] == ["failed case"]
    low, high = axes.get_xlim()
    assert low < -8 and high > -4  # the edge points drawn whole


def test_a_missing_column_exits_with_2(table):
    finished = subprocess.run([sys.executable, SCRIPT, table, "--x", "speed", "--y", "spin",
                               "--metric", "quality"], capture_output=True, text=True)
    assert finished.returncode == 2
    assert "no column 'quality'" in finished.stderr
