"""plot_probes.py: one panel per physical quantity, SI units on every axis, named curves."""

import re

import numpy as np

from plot_probes import make_probe_figure
from probe_quantities import probe_kind, probe_panels
from run_folder import read_run_probes

UNIT_IN_LABEL = re.compile(r"^.+ \[(.+)\]$")


def legend_texts(axes):
    return [text.get_text() for text in axes.get_legend().get_texts()]


def test_contact_probe_has_one_panel_per_quantity(capture_run):
    time, probes = read_run_probes(capture_run)
    figure = make_probe_figure("hull", time, probes["hull"])
    axes = figure.axes
    assert [a.get_ylabel() for a in axes] == [
        "number of contacts [–]", "force [N]", "moment [N m]", "penetration [m]"]
    assert axes[-1].get_xlabel() == "time [s]"
    assert legend_texts(axes[1])[:2] == ["normal force on hull (Σ F_n)",
                                         "friction force on hull (Σ |f_t|)"]
    assert "deepest penetration into hull" in legend_texts(axes[3])


def test_every_column_of_the_run_has_a_known_si_unit(capture_run):
    _, probes = read_run_probes(capture_run)
    kinds = {name: probe_kind(columns) for name, columns in probes.items()}
    assert kinds == {"rates": "body_velocity", "hull": "contact", "energy": "energy",
                     "threads": "max_tension", "grab": "capture"}
    for name, columns in probes.items():
        raw_names = {f"{name}.{component}" for component in columns}
        for panel in probe_panels(name, columns):
            unit = UNIT_IN_LABEL.match(panel.ylabel).group(1)
            assert unit in ("–", "m", "m/s", "rad/s", "N", "N m", "J"), panel.ylabel
            assert all(curve.label not in raw_names for curve in panel.curves)


def test_energy_panel_carries_the_balance(capture_run):
    _, probes = read_run_probes(capture_run)
    (panel,) = probe_panels("energy", probes["energy"])
    balance = panel.curves[-1]
    assert balance.label.startswith("balance")
    e = probes["energy"]
    np.testing.assert_allclose(
        balance.values, e["kinetic"] + e["strain"] + e["gravity"] + e["dissipated"] - e["work"])


def test_unknown_columns_say_their_unit_is_unknown():
    (panel,) = probe_panels("custom", {"speed": np.zeros(3)})
    assert panel.ylabel == "speed (not an ancfnet column) [unknown unit]"
