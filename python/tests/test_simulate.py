"""simulate: the same numbers as `vantage simulate --json` (wall-clock times aside), arrays and
files alike, per-trial values, and bad input as ValueError naming the argument."""

import numpy as np
import pytest

from conftest import LAYOUTS, assert_same, cli_json


def without_times(report):
    """The report without the per-solve wall-clock times, which differ from run to run."""
    for summary in report["estimators"].values():
        summary.pop("time_us")
    for values in report.get("per_trial", {}).get("estimators", {}).values():
        values.pop("time_us")
    return report


def test_simulate_matches_the_cli_on_the_affine_camera(vantage):
    path = str(LAYOUTS / "satellite.json")
    result = vantage.simulate(path, trials=60, seed=7, noise_px=0.5, threads=2)
    cli = cli_json("simulate", path, "--trials", "60", "--seed", "7", "--noise-px", "0.5",
                   "--threads", "2", "--quiet")
    assert_same(without_times(result.to_dict()), without_times(cli))
    assert result.bound_check.trials == 60


def test_simulate_matches_the_cli_on_the_pinhole_camera_at_the_worst_viewpoint(vantage):
    path = str(LAYOUTS / "satellite.json")
    result = vantage.simulate(path, trials=20, camera="pinhole", snr_db=50.0, range=20.0,
                              viewpoint="worst", methods=["perspective", "oi-foam"],
                              per_trial=True)
    cli = cli_json("simulate", path, "--trials", "20", "--camera", "pinhole", "--snr-db", "50",
                   "--range", "20", "--viewpoint", "worst", "--methods", "perspective,oi-foam",
                   "--per-trial", "--quiet")
    assert_same(without_times(result.to_dict()), without_times(cli))
    assert sorted(result.estimators) == ["oi-foam", "perspective"]
    assert "bound_check" not in result.to_dict()  # the bound is for the affine camera
    assert result.per_trial.estimators["perspective"]["rot_err_deg"].shape == (20,)


def test_arrays_and_files_give_the_same_simulation(vantage):
    # A layout without normals: on a body the views are drawn from its trackable directions.
    layout = vantage.load_layout(LAYOUTS / "mocap_rigid_body.csv")
    from_file = without_times(vantage.simulate(layout, trials=30).to_dict())
    from_points = without_times(vantage.simulate(points=layout.entries, trials=30).to_dict())
    for report in (from_file, from_points):
        report.pop("layout")
        report["config"]["layout"].pop("name")
    assert_same(from_points, from_file)


def test_noise_free_affine_views_keep_every_error_under_the_bound(vantage):
    result = vantage.simulate(vectors=np.eye(3), trials=50)
    assert result.bound_check.passed is True
    assert result.bound_check.max_error_deg <= result.bound_check.bound_deg + 1e-9


@pytest.mark.parametrize("kwargs, message", [
    ({"noise_px": -1.0}, "noise_px"),
    ({"camera": "fisheye"}, "camera"),
    ({"viewpoint": "best"}, "viewpoint"),
    ({"principal_point": [1.0]}, "principal_point"),
    ({"trials": 0}, "trials"),
    ({"methods": ["no-such-estimator"]}, "methods"),
])
def test_bad_options_raise_value_error_naming_the_argument(vantage, kwargs, message):
    with pytest.raises(ValueError, match=message):
        vantage.simulate(str(LAYOUTS / "satellite.json"), **kwargs)


def test_pinhole_needs_points(vantage):
    with pytest.raises(ValueError, match="pinhole"):
        vantage.simulate(vectors=np.eye(3), camera="pinhole")
