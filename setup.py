"""Builds the Python module with the project's CMake for `pip install --no-build-isolation .`.

The module is configured in build/pip (Release, no tests or benchmarks) with the Python that runs
pip, or taken from the build folder ANCFNET_BUILD_DIR (built there first, not reconfigured) when it
is set, e.g. ANCFNET_BUILD_DIR=build/release to reuse `make build`'s."""
import os
import pathlib
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent
SETUPTOOLS_DIR = ROOT / "build" / "setuptools"  # setuptools' own files, out of the source tree


class CMakeBuild(build_ext):
    """Builds the CMake target ancfnet_python and copies the module where setuptools wants it."""

    def build_extension(self, ext):
        build_dir = os.environ.get("ANCFNET_BUILD_DIR")
        if build_dir:
            build_dir = pathlib.Path(build_dir).resolve()
        else:
            build_dir = ROOT / "build" / "pip"
            subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build_dir),
                            "-DCMAKE_BUILD_TYPE=Release", "-DANCFNET_BUILD_TESTS=OFF",
                            "-DANCFNET_BUILD_BENCHMARKS=OFF",
                            f"-DPython3_EXECUTABLE={sys.executable}"], check=True)
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "ancfnet_python",
                        "-j", str(os.cpu_count())], check=True)
        module = next((build_dir / "python").glob("ancfnet*.so"))
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(module, target)


SETUPTOOLS_DIR.mkdir(parents=True, exist_ok=True)
setup(packages=[], ext_modules=[Extension("ancfnet", sources=[])],
      cmdclass={"build_ext": CMakeBuild},
      options={"build": {"build_base": str(SETUPTOOLS_DIR)},
               "egg_info": {"egg_base": str(SETUPTOOLS_DIR)}})
