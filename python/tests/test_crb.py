"""vantage.crb (docs/math.md §22): the typed result carries exactly the fields of
`vantage crb --json`, the covariance is 6 x 6 and its rotation trace is rot_rms_deg, and bad
input raises ValueError naming the argument."""

import math

import numpy as np
import pytest

from conftest import LAYOUTS, assert_same, cli_json

CUBE = str(LAYOUTS / "apriltag_cube.yaml")
# sqrt of a trace of three doubles and a change of units: a few roundings.
TRACE_ROUNDING = 1e-12


def test_crb_is_the_cli_report(vantage):
    result = vantage.crb(CUBE, distance=2, focal=900, noise_px=0.3, direction=[0.3, 0.2, 0.9])
    cli = cli_json("crb", CUBE, "--distance", "2", "--focal", "900", "--noise-px", "0.3",
                   "--direction", "0.3,0.2,0.9")
    assert_same(result.to_dict(), cli)
    assert isinstance(result, vantage.CrbReport)
    assert isinstance(result.worst, vantage.CrbBound)
    assert result.worst.rot_rms_deg == cli["worst"]["rot_rms_deg"]
    assert result.affine_bound_deg == cli["affine_bound_deg"]
    at = result.at_direction
    assert at is not None and at.covariance is not None
    assert at.covariance.shape == (6, 6)
    assert math.isclose(math.degrees(math.sqrt(np.trace(at.covariance[3:, 3:]))),
                        at.rot_rms_deg, rel_tol=TRACE_ROUNDING)
    assert result.percentiles["p50"] <= result.percentiles["p99"] <= result.worst.rot_rms_deg


def test_past_45_degrees_the_bound_is_unbounded_not_a_figure(vantage):
    # The satellite at 10 units: the worst direction's first-order rot_rms passes 45 degrees
    # (docs/math.md §22, "Unbounded"): no figure, the flag, and the percentiles stay figures.
    satellite = str(LAYOUTS / "satellite.json")
    result = vantage.crb(satellite, distance=10, focal=1000, noise_px=0.3, samples=2000)
    cli = cli_json("crb", satellite, "--distance", "10", "--focal", "1000", "--noise-px", "0.3",
                   "--samples", "2000")
    assert_same(result.to_dict(), cli)
    assert result.status == "ok"
    assert result.worst.unbounded and not result.worst.trackable
    assert result.worst.rot_rms_deg is None and result.worst.trans_rms is None
    assert result.unbounded_fraction == cli["unbounded_fraction"]
    assert result.percentiles["p99"] <= 45.0


def test_crb_sweep_has_one_row_per_distance(vantage):
    result = vantage.crb(CUBE, distance=2, focal=900, noise_px=0.3, sweep_distance=(1, 3, 3),
                         samples=500)
    assert [row.distance for row in result.sweep_distance] == [1.0, 2.0, 3.0]


def test_crb_bad_input_names_the_argument(vantage):
    with pytest.raises(ValueError) as error:
        vantage.crb(CUBE, distance=2, focal=900, noise_px=0)
    assert error.value.field == "noise_px"
    # Issue 36, item 8: a pair for the triple raised pybind11's "Unable to cast".
    with pytest.raises(ValueError) as error:
        vantage.crb(CUBE, distance=2, focal=900, noise_px=0.2, sweep_distance=(1, 2))
    assert error.value.field == "sweep_distance"
    # Issue 36, item 5: f^2 / S^2 overflowed and every direction was "untrackable".
    with pytest.raises(ValueError) as error:
        vantage.crb(CUBE, distance=2, focal=1e300, noise_px=0.3)
    assert error.value.field == "focal"


def test_crb_says_when_the_pose_is_not_determined(vantage):
    # Issue 36, item 5: a camera 1e5 away sees the markers but cannot determine the pose; the
    # status says so with the CLI's message and, as the CLI exits 1, NumericalError is raised.
    with pytest.raises(vantage.NumericalError) as error:
        vantage.crb(CUBE, distance=1e5, focal=900, noise_px=0.3, samples=500)
    assert error.value.status == "ill_conditioned"
    result = error.value.result
    assert isinstance(result, vantage.CrbReport)
    assert result.status == "ill_conditioned"
    assert result.worst is None
    assert "not determined to first order" in result.message
    assert "not determined to first order" in str(error.value)
    assert vantage.crb(CUBE, distance=2, focal=900, noise_px=0.3, samples=500).message is None
