"""Shared helpers of the pytest suite: the built CLI (VANTAGE_CLI, set by ctest), the example
files, and a comparison of a result's to_dict() with the CLI's --json output."""

import json
import math
import os
import pathlib
import subprocess

import pytest

SOURCE = pathlib.Path(os.environ.get("VANTAGE_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
LAYOUTS = SOURCE / "examples" / "layouts"
CORRESPONDENCES = SOURCE / "examples" / "correspondences"
CLI = os.environ.get("VANTAGE_CLI", "vantage")

# The module and the CLI run the same deterministic C++ code, and JSON prints doubles with
# round-trip precision: the numbers agree to the last bit. A relative 1e-12 leaves room for
# nothing but printing.
SAME_NUMBER = 1e-12

EXAMPLE_LAYOUTS = sorted(
    p.name for p in LAYOUTS.iterdir() if p.suffix in (".json", ".csv", ".yaml", ".yml"))


def run_cli(*args, expect=0):
    """Runs the vantage CLI; returns (stdout, stderr) after checking the exit status."""
    run = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, check=False)
    assert run.returncode == expect, run.stderr
    return run.stdout, run.stderr


def cli_json(*args):
    out, err = run_cli(*args, "--json")
    assert err == ""
    return json.loads(out)


def cli_error(*args):
    """The message of a bad-input run (exit 2): stderr without the 'vantage: error: ' prefix."""
    out, err = run_cli(*args, expect=2)
    assert out == ""
    prefix = "vantage: error: "
    assert err.startswith(prefix) and err.count("\n") == 1, err
    return err[len(prefix):].rstrip("\n")


def assert_same(python, cli, path="result"):
    """Equal JSON values; numbers to SAME_NUMBER relative."""
    if isinstance(cli, dict):
        assert isinstance(python, dict), path
        assert list(python) == list(cli), f"{path}: fields {list(python)} != {list(cli)}"
        for key in cli:
            assert_same(python[key], cli[key], f"{path}.{key}")
    elif isinstance(cli, list):
        assert isinstance(python, list) and len(python) == len(cli), path
        for i, (p, c) in enumerate(zip(python, cli)):
            assert_same(p, c, f"{path}[{i}]")
    elif isinstance(cli, float) or isinstance(python, float):
        assert isinstance(python, (int, float)) and not isinstance(python, bool), path
        assert math.isclose(python, cli, rel_tol=SAME_NUMBER, abs_tol=SAME_NUMBER), \
            f"{path}: {python} != {cli}"
    else:
        assert python == cli, f"{path}: {python!r} != {cli!r}"


@pytest.fixture
def vantage():
    import vantage as module
    return module
