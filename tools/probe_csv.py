"""Reads the probes.csv that ancfnet writes (docs/scene-format.md, "probes.csv")."""

import csv
import warnings

import numpy as np


def read_probes(path, fail):
    """Returns (time, {probe name: {component: values}}) in the order of the columns.

    `fail(message)` is called (and must not return) for a missing, empty or malformed file.
    """
    if not path.is_file():
        fail(f"{path}: no such file")
    with path.open(newline="") as file:
        header = next(csv.reader(file), None)
    if not header or header[0] != "time" or len(header) < 2:
        fail(f"{path}: empty, or not a probe CSV (expected a header 'time,NAME.COMPONENT,...')")
    try:
        with warnings.catch_warnings():  # a header without rows is reported below, not warned
            warnings.simplefilter("ignore", UserWarning)
            data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    except ValueError as error:
        fail(f"{path}: {error}")
    if data.shape[0] == 0:
        fail(f"{path}: no data rows")
    probes = {}
    for index, column in enumerate(header[1:], start=1):
        name, _, component = column.rpartition(".")
        probes.setdefault(name or column, {})[component] = data[:, index]
    return data[:, 0], probes
