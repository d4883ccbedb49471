"""setup.py says what is missing, in one message, before pip's own error would (issue 39, item 6:
under a Python without `wheel`, pip said only "invalid command 'bdist_wheel'")."""

import subprocess
import sys

from conftest import SOURCE

SETUP = str(SOURCE / "setup.py")


def run_setup(*python_flags):
    return subprocess.run([sys.executable, *python_flags, SETUP, "--name"], capture_output=True,
                          text=True, check=False, cwd=str(SOURCE))


def test_a_python_without_the_build_tools_is_told_which_and_how():
    # -S: no site directories, so neither setuptools, wheel nor numpy can be imported.
    run = run_setup("-S")
    assert run.returncode != 0
    assert run.stdout == ""
    message = run.stderr.strip()
    assert "\n" not in message
    assert message.startswith(f"vantage: {sys.executable} cannot import setuptools")
    assert "numpy (python3-numpy)" in message
    assert "/usr/bin/python3 -m venv --system-site-packages DIR" in message


def test_debians_python_has_them():
    run = run_setup()
    assert run.returncode == 0, run.stderr
    assert run.stdout.strip() == "vantage"
