"""Fixtures of the tests of the Python module: the repository's scenes and the CLI to compare with.

Run by CTest (test python.api) with PYTHONPATH set to the build's module directory and ANCFNET_CLI
to the command-line tool."""

import os
import subprocess

import pytest

from scenes import short_scene


@pytest.fixture
def pendulum_text():
    """The flexible pendulum of examples/pendulum.yaml over its first 0.1 s (10 output steps)."""
    return short_scene("pendulum", 0.1)


@pytest.fixture
def cli():
    """Runs the ancfnet command-line tool with the given arguments; returns the finished process."""
    binary = os.environ.get("ANCFNET_CLI")
    if not binary:
        pytest.skip("ANCFNET_CLI is not set (CTest sets it)")

    def run(*args):
        return subprocess.run([binary, *map(str, args)], capture_output=True, text=True)

    return run
