"""The repository's example scenes as text, for the tests."""

import pathlib

ROOT = pathlib.Path(__file__).resolve().parents[2]


def short_scene(name, end_time=None):
    """The text of examples/NAME.yaml, with its end time cut to END_TIME (s) when given."""
    text = (ROOT / "examples" / f"{name}.yaml").read_text()
    lines = [f"  end_time: {end_time}" if end_time and line.startswith("  end_time:") else line
             for line in text.splitlines()]
    return "\n".join(lines) + "\n"
