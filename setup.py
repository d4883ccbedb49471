"""Builds the extension vantage._vantage with CMake for `pip install --no-build-isolation .`.

The C++ libraries and the pybind11 module are built by the project's own CMakeLists.txt (no
second build description): a Release build (-O3 -DNDEBUG, no -g, unity batches) of the target
vantage_python only, in build/setuptools/cmake. The extension is stripped of its symbols and
debug info as it is copied into the wheel.

VANTAGE_CMAKE_BUILD_DIR=<dir> reuses an existing, configured CMake build directory instead (the
ctest install test does, so that it does not rebuild the libraries): only vantage_python is
brought up to date there, and the copy is stripped all the same.
VANTAGE_CMAKE_ARGS adds arguments to the configure step (e.g. -DVANTAGE_WITH_NLOPT=OFF);
VANTAGE_BUILD_JOBS sets the parallel jobs (default: the cores).
"""

import glob
import importlib.util
import os
import shlex
import shutil
import subprocess
import sys
import sysconfig


def _missing_build_tools():
    """What this Python lacks to build and use vantage, each with its Debian package."""
    missing = []
    if importlib.util.find_spec("setuptools") is None:
        missing.append("setuptools (python3-setuptools)")
    # setuptools 70.1 and later build wheels themselves; before, bdist_wheel is the wheel
    # package's ("invalid command 'bdist_wheel'" without it).
    if (importlib.util.find_spec("setuptools.command.bdist_wheel") is None
            if importlib.util.find_spec("setuptools") else True):
        if importlib.util.find_spec("wheel") is None:
            missing.append("wheel (python3-wheel)")
    if importlib.util.find_spec("numpy") is None:
        missing.append("numpy (python3-numpy), which the package imports")
    return missing


_MISSING = _missing_build_tools()
if _MISSING:
    sys.exit(f"vantage: {sys.executable} cannot import " + ", ".join(_MISSING) + ". Install "
             "with Debian's Python: `/usr/bin/python3 -m venv --system-site-packages DIR`, then "
             "`DIR/bin/pip install --no-build-isolation --no-index .` (README, \"Python\").")

from setuptools import Extension, setup  # noqa: E402 (after the check of what is missing)
from setuptools.command.build_ext import build_ext  # noqa: E402

SOURCE_DIR = os.path.dirname(os.path.abspath(__file__))


def _run(command):
    print("vantage:", " ".join(shlex.quote(part) for part in command), flush=True)
    subprocess.run(command, check=True)


class CMakeBuild(build_ext):
    """build_ext that builds vantage._vantage with CMake instead of compiling sources itself."""

    def build_extension(self, ext):
        build_dir = os.environ.get("VANTAGE_CMAKE_BUILD_DIR")
        if build_dir:
            build_dir = os.path.abspath(build_dir)
            if not os.path.isfile(os.path.join(build_dir, "CMakeCache.txt")):
                sys.exit(f"VANTAGE_CMAKE_BUILD_DIR={build_dir}: not a configured CMake build directory")
        else:
            build_dir = os.path.join(SOURCE_DIR, "build", "setuptools", "cmake")
            _run([
                "cmake", "-S", SOURCE_DIR, "-B", build_dir,
                "-DCMAKE_BUILD_TYPE=Release",
                "-DVANTAGE_BUILD_TESTS=OFF", "-DVANTAGE_BUILD_BENCH=OFF",
                "-DVANTAGE_BUILD_EXAMPLES=OFF", "-DVANTAGE_BUILD_VIEWER=OFF",
                "-DVANTAGE_WITH_PLOT=OFF",
                # A build from scratch: unity batches compile the libraries in about half the
                # CPU time (README, "Build options").
                "-DVANTAGE_UNITY_BUILD=ON",
                f"-DPython3_EXECUTABLE={sys.executable}",
            ] + shlex.split(os.environ.get("VANTAGE_CMAKE_ARGS", "")))
        jobs = os.environ.get("VANTAGE_BUILD_JOBS", str(os.cpu_count() or 1))
        print("vantage: building the C++ libraries and the extension (from scratch about 4 "
              "minutes on 2 cores; `pip install -v` shows CMake's progress)", flush=True)
        _run(["cmake", "--build", build_dir, "--target", "vantage_python", "-j", jobs])
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        built = glob.glob(os.path.join(build_dir, "python", "vantage", "_vantage" + suffix))
        if len(built) != 1:
            sys.exit(f"vantage: the CMake build in {build_dir} made no _vantage{suffix} "
                     "(is it configured for this Python? Python3_EXECUTABLE)")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built[0], target)
        _run(["strip", "--strip-unneeded", target])


setup(
    ext_modules=[Extension("vantage._vantage", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": os.path.join("build", "setuptools")},
             "egg_info": {"egg_base": os.path.join("build", "setuptools")}},
)
