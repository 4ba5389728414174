#!/usr/bin/env bash
# `pip install --no-build-isolation .` with Debian's pip, setuptools and wheel, offline: installs
# the module built in the build folder (ANCFNET_BUILD_DIR, setup.py) into a scratch folder and
# imports it from there. Usage: bash python/pip_install_test.sh <python3> <build folder> <repo root>
set -euo pipefail

python="${1:?usage: pip_install_test.sh <python3> <build folder> <repo root>}"
build="${2:?usage: pip_install_test.sh <python3> <build folder> <repo root>}"
root="${3:?usage: pip_install_test.sh <python3> <build folder> <repo root>}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

cd "$root"
ANCFNET_BUILD_DIR="$build" "$python" -m pip install --quiet --no-build-isolation --no-deps \
  --no-index --no-cache-dir --disable-pip-version-check --target "$work/site" . >"$work/log" 2>&1 ||
  { cat "$work/log" >&2; echo "FAIL: pip install exited with an error" >&2; exit 1; }
cd "$work"
PYTHONPATH="$work/site" "$python" - "$work/site" "$root/examples/pendulum.yaml" <<'PY'
import pathlib, sys
import ancfnet
site, scene_file = map(pathlib.Path, sys.argv[1:])
assert pathlib.Path(ancfnet.__file__).parent == site, ancfnet.__file__
assert ancfnet.load_scene(scene_file).analysis == "dynamic"
PY
