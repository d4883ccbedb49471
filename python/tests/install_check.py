"""The real install, as a user does it (README "Python"): a fresh venv with Debian's numpy
(--system-site-packages), `pip install --no-build-isolation --no-index .` of the repository,
then, outside the source tree, the typed session of examples/python/typed_session.py, mypy
--strict over it (the installed stubs and py.typed), mypy's stubtest of the extension's stub
against the installed extension, and the installed extension free of debug info. Prints the seconds each step took and the installed size.

    python3 install_check.py SOURCE_DIR CMAKE_BUILD_DIR

CMAKE_BUILD_DIR is passed to setup.py as VANTAGE_CMAKE_BUILD_DIR, so that pip reuses the
already-built libraries (only the target vantage_python is brought up to date) instead of
building the C++ from scratch: CI time.
"""

import os
import pathlib
import subprocess
import sys
import tempfile
import time


def run(command, **kwargs):
    started = time.monotonic()
    done = subprocess.run(command, capture_output=True, text=True, check=False, **kwargs)
    if done.returncode != 0:
        sys.exit(f"install_check: {' '.join(map(str, command))} failed ({done.returncode}):\n"
                 f"{done.stdout}\n{done.stderr}")
    return done.stdout, time.monotonic() - started


def tree_bytes(path):
    return sum(f.stat().st_size for f in path.rglob("*") if f.is_file())


def main():
    source, build = (pathlib.Path(p).resolve() for p in sys.argv[1:3])
    with tempfile.TemporaryDirectory(prefix="vantage-venv-") as temp:
        temp = pathlib.Path(temp)
        venv = temp / "venv"
        python = venv / "bin" / "python"
        _, t_venv = run(["/usr/bin/python3", "-m", "venv", "--system-site-packages", venv])
        env = dict(os.environ, VANTAGE_CMAKE_BUILD_DIR=str(build), PIP_NO_INDEX="1",
                   PIP_DISABLE_PIP_VERSION_CHECK="1", PIP_NO_CACHE_DIR="1")
        env.pop("PYTHONPATH", None)  # the installed package, not the build tree's
        _, t_pip = run([python, "-m", "pip", "install", "--no-build-isolation", "--no-index",
                        "--no-deps", source], env=env)

        work = temp / "work"  # outside the source tree: nothing there shadows the install
        work.mkdir()
        out, _ = run([python, "-c", "import importlib.metadata as m, vantage; "
                      "print(vantage.__file__, vantage.__version__, m.version('vantage'))"],
                     env=env, cwd=work)
        path, version, distribution = out.split()
        if version != distribution:
            sys.exit(f"install_check: vantage.__version__ {version} (CMake's project version) "
                     f"!= {distribution} (pyproject.toml)")
        package = pathlib.Path(path).parent
        if venv not in package.parents:
            sys.exit(f"install_check: imported vantage from {package}, not from the venv")
        session = source / "examples" / "python" / "typed_session.py"
        out, t_session = run([python, session, source / "examples"], env=env, cwd=work)
        if "p-bar_min 0.991366" not in out:
            sys.exit(f"install_check: the typed session printed an unexpected report:\n{out}")

        _, t_mypy = run([python, "-m", "mypy", "--strict", "--no-incremental",
                         "--cache-dir", temp / "mypy", session], env=env, cwd=work)
        # The stub of the extension names exactly what the installed extension has.
        _, t_stubtest = run([python, "-m", "mypy.stubtest", "vantage._vantage",
                             "--mypy-config-file", os.devnull, "--allowlist",
                             source / "python" / "tests" / "stubtest_allowlist.txt"],
                            env=dict(env, MYPY_CACHE_DIR=str(temp / "stubtest")), cwd=work)

        (extension,) = package.glob("_vantage*.so")
        sections, _ = run(["readelf", "-S", "-W", extension])
        debug = [line.split()[1] for line in sections.splitlines()
                 if ".debug" in line or ".symtab" in line]
        if debug:
            sys.exit(f"install_check: the installed extension carries {debug}")
        for name in ("py.typed", "_vantage.pyi"):
            if not (package / name).is_file():
                sys.exit(f"install_check: the install lacks vantage/{name}")
        print(f"venv {t_venv:.1f} s, pip install {t_pip:.1f} s, typed session {t_session:.1f} s, "
              f"mypy {t_mypy:.1f} s, stubtest {t_stubtest:.1f} s; extension {extension.stat().st_size / 1e6:.2f} MB, "
              f"package {tree_bytes(package) / 1e6:.2f} MB")


if __name__ == "__main__":
    main()
