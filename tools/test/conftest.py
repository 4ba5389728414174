"""Fixtures of the tests of the plotting tools: a small capture run made by the CLI, once.

Run by CTest (test tools.plots, label python) with ANCFNET_CLI set to the command-line tool; the
scripts of tools/ are imported from the folder above."""

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

TOOLS = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(TOOLS))


@pytest.fixture(scope="session")
def cli():
    """Runs the ancfnet command-line tool with the given arguments; returns the finished
    process."""
    binary = os.environ.get("ANCFNET_CLI")
    if not binary:
        pytest.skip("ANCFNET_CLI is not set (CTest sets it)")

    def run(*args, env=None):
        """`env`: variables to set or change for the tool."""
        return subprocess.run([binary, *map(str, args)], capture_output=True, text=True,
                              env=None if env is None else {**os.environ, **env})

    return run


@pytest.fixture(scope="session")
def capture_run(cli, tmp_path_factory):
    """The output folder of tools/test/small_capture.yaml (13 outputs, 0 to 0.06 s)."""
    run_dir = tmp_path_factory.mktemp("small_capture")
    finished = cli("run", Path(__file__).with_name("small_capture.yaml"), "-o", run_dir, "-q")
    assert finished.returncode == 0, finished.stderr
    return run_dir


@pytest.fixture
def run_copy(capture_run, tmp_path):
    """A copy of capture_run that a test may change."""
    return Path(shutil.copytree(capture_run, tmp_path / "run"))
