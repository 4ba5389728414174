"""The output folder of an ancfnet run, as the report and the animation read it.

`run` writes probes.csv, cables.pvd with one .vtp frame per output, and summary.json
(docs/scene-format.md, "Outputs"). Every missing piece is a RunDataError whose message names
the file; the scripts turn it into one line on stderr and exit code 2.
"""

import sys
from pathlib import Path

from probe_csv import read_probes

EXIT_INPUT_ERROR = 2


class RunDataError(Exception):
    """A run folder without the files or data asked for; the message says which."""


def check_run_dir(run_dir):
    """`run_dir` as a Path; RunDataError when it is not a folder."""
    run_dir = Path(run_dir)
    if not run_dir.is_dir():
        raise RunDataError(f"{run_dir}: no such folder (give the output folder of `ancfnet run`)")
    return run_dir


def read_run_probes(run_dir):
    """(time, probes) of RUN_DIR/probes.csv (probe_csv.read_probes)."""
    def fail(message):
        raise RunDataError(message)
    return read_probes(check_run_dir(run_dir) / "probes.csv", fail)


def warn(message):
    """A note on stderr that does not stop the script."""
    print(f"note: {message}", file=sys.stderr)


def exit_on_run_data_error(program, main):
    """Runs `main()` and returns its exit code; a RunDataError prints one line, returns 2."""
    try:
        return main()
    except RunDataError as error:
        print(f"{program}: error: {error}", file=sys.stderr)
        return EXIT_INPUT_ERROR
