"""vantage.tre (docs/math.md §23): the typed result carries exactly the fields of
`vantage tre --json` (the same seeded Monte Carlo included), the isotropic RMS is Fitzpatrick,
West & Maurer's formula computed here with numpy, the covariance's trace is the RMS², and bad
input raises ValueError naming the argument."""

import json
import math

import numpy as np
import pytest

from conftest import SOURCE, assert_same, cli_json

TOOLS = SOURCE / "examples" / "tools"
NDI = str(TOOLS / "ndi_like.json")
WEST = str(TOOLS / "west_planar.json")
# sqrt of a trace of three doubles: a few roundings.
TRACE_ROUNDING = 1e-12
# The agreement of the library's isotropic RMS with Fitzpatrick's formula.
FITZPATRICK = 1e-9


def fitzpatrick(points, target, fle_rms):
    """Fitzpatrick 1998, Eq. (23.3): TRE^2 = FLE^2 / N (1 + 1/3 sum_k d_k^2 / f_k^2), in the
    principal axes of the markers."""
    points = np.asarray(points, dtype=float)
    centred = points - points.mean(axis=0)
    _, axes = np.linalg.eigh(centred.T @ centred)
    d = np.asarray(target, dtype=float) - points.mean(axis=0)
    total = 0.0
    for k in range(3):
        axis = axes[:, k]
        f2 = np.mean(np.sum(centred**2, axis=1) - (centred @ axis) ** 2)
        d2 = d @ d - (d @ axis) ** 2
        total += d2 / f2
    return fle_rms * math.sqrt((1.0 + total / 3.0) / len(points))


def test_tre_is_the_cli_report(vantage):
    result = vantage.tre(NDI, targets=[[0, 0, -150], [10, 0, -100]], fle_sigma=(0.0995, 0.2985),
                         direction=[0.3, 0, 1], monte_carlo=2000, seed=3)
    cli = cli_json("tre", NDI, "--target", "0,0,-150", "--target", "10,0,-100", "--fle-sigma",
                   "0.0995,0.2985", "--direction", "0.3,0,1", "--monte-carlo", "2000",
                   "--seed", "3")
    assert_same(result.to_dict(), cli)
    assert isinstance(result, vantage.TreReport)
    assert len(result.targets) == 2
    first = result.targets[0]
    assert isinstance(first.worst, vantage.TreExtreme)
    assert first.worst.rms == cli["targets"][0]["worst"]["rms"]
    assert first.worst.certified and first.best.certified
    assert first.best.rms <= first.worst.rms
    assert first.rms_isotropic is None  # anisotropic FLE
    at = first.at_direction
    assert at is not None and at.tracked and at.covariance is not None
    assert at.covariance.shape == (3, 3)
    assert math.isclose(math.sqrt(np.trace(at.covariance)), at.rms, rel_tol=TRACE_ROUNDING)
    assert first.monte_carlo is not None and first.monte_carlo.trials == 2000
    np.testing.assert_allclose(first.monte_carlo.direction, at.direction)
    assert result.fle["kind"] == "anisotropic"


def test_isotropic_rms_is_fitzpatricks_formula(vantage):
    points = np.array([[-40, -30, 0], [45, -25, 0], [35, 40, 0], [-40, 15, 0]], dtype=float)
    targets = np.array([[0, 0, -100], [0, -150, 0], [12, 7, -80]], dtype=float)
    from_file = vantage.tre(WEST, targets=targets, fle_rms=0.3)
    from_points = vantage.tre(points=points, targets=targets, fle_rms=0.3)
    assert_same(from_points.to_dict(), from_file.to_dict())
    for target, report in zip(targets, from_file.targets):
        truth = fitzpatrick(points, target, 0.3)
        assert math.isclose(report.rms_isotropic, truth, rel_tol=FITZPATRICK)
        # Isotropic FLE and no normals: every line of sight gives the formula.
        assert math.isclose(report.worst.rms, truth, rel_tol=FITZPATRICK)
        assert math.isclose(report.best.rms, truth, rel_tol=FITZPATRICK)
        assert report.worst.closed_form
    assert from_file.fle == {"kind": "isotropic", "rms": 0.3}


def test_one_target_as_a_vector(vantage):
    one = vantage.tre(NDI, targets=[0, 0, -150], fle_rms=0.33)
    rows = vantage.tre(NDI, targets=[[0, 0, -150]], fle_rms=0.33)
    assert_same(one.to_dict(), rows.to_dict())
    np.testing.assert_array_equal(one.targets[0].target, [0.0, 0.0, -150.0])


@pytest.mark.parametrize("kwargs, field", [
    ({"targets": [0, 0, -150]}, "fle_rms"),
    ({"targets": [0, 0, -150], "fle_rms": 0.3, "fle_sigma": (0.1, 0.3)}, "fle_rms"),
    ({"targets": [0, 0, -150], "fle_rms": -1.0}, "fle_rms"),
    ({"targets": [0, 0, -150], "fle_sigma": (0.0, 0.0)}, "fle_sigma"),
    ({"targets": [0, 0, -150], "fle_sigma": (0.1, 0.2, 0.3)}, "fle_sigma"),
    ({"fle_rms": 0.3}, "targets"),
    ({"targets": [0, 0], "fle_rms": 0.3}, "targets"),
    ({"targets": [0, 0, -150], "fle_rms": 0.3, "direction": [0, 0, 0]}, "direction"),
    ({"targets": [0, 0, -150], "fle_rms": 0.3, "monte_carlo": 10}, "monte_carlo"),
    ({"targets": [0, 0, -150], "fle_rms": 0.3, "threads": -1}, "threads"),
    # Lengths outside [1e-50, 1e50] (issue 36: these returned rms inf or 0, certified).
    ({"targets": [1e200, 0, 0], "fle_rms": 0.25}, "targets"),
    ({"targets": [1e45, 0, 0], "fle_rms": 1e20}, "targets"),
    ({"targets": [0, 0, -150], "fle_rms": 1e-300}, "fle_rms"),
    ({"targets": [0, 0, -150], "fle_sigma": (1e300, 1e300)}, "fle_sigma"),
])
def test_tre_bad_input_names_the_argument(vantage, kwargs, field):
    with pytest.raises(ValueError) as error:
        vantage.tre(NDI, **kwargs)
    assert error.value.field == field


def test_tre_needs_points(vantage):
    with pytest.raises(ValueError) as error:
        vantage.tre(str(SOURCE / "examples" / "layouts" / "triad.json"), targets=[0, 0, 1],
                    fle_rms=0.3)
    assert error.value.field == "points"


def test_a_target_tracked_from_nowhere_raises_numerical_error(vantage, tmp_path):
    # Issue 36, item 5: the CLI exits 1 with the reason; Python returned the report silently.
    # The drone's markers face up; the workspace looks at it from below.
    drone = json.loads((SOURCE / "examples" / "layouts" / "drone.json").read_text())
    drone["workspace"] = {"axis": [0, 0, -1], "half_angle_deg": 10}
    path = tmp_path / "from_below.json"
    path.write_text(json.dumps(drone))
    with pytest.raises(vantage.NumericalError) as error:
        vantage.tre(str(path), targets=[0, 0, -1], fle_rms=0.1)
    assert error.value.status == "untracked"
    assert "the TRE is not defined" in str(error.value)
    assert isinstance(error.value.result, vantage.TreReport)
    assert error.value.result.targets[0].worst.status == "untracked"
