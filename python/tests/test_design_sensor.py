"""vantage.design(objective='camera' or 'tracker') (docs/math.md §21, "In design"): the CLI's
JSON, the augmented layout whose sensor value vantage.analyze reports, and errors by keyword."""

import json

import numpy as np
import pytest

from conftest import assert_same, cli_json

MARKERS = [[0, 0, 0], [0.06, 0, 0], [0, 0.06, 0], [0.05, 0.05, 0.02]]
CANDIDATES = [[0.3, 0.05, 0.01], [-0.25, 0.2, 0.05], [0.1, -0.3, 0.03], [0.02, 0.1, 0.2],
              [-0.1, -0.05, 0.1], [0.5, 0.4, -0.05]]
CAMERA = {"distance": 2.0, "focal": 1000.0, "noise_px": 0.3, "crb_samples": 400}


@pytest.fixture
def patch_file(tmp_path):
    path = tmp_path / "patch.json"
    path.write_text(json.dumps({"name": "patch", "points": MARKERS, "candidates": CANDIDATES}))
    return str(path)


def test_camera_design_is_the_clis_and_analyze_reports_its_value(vantage, patch_file):
    result = vantage.design(patch_file, add=2, objective="camera", **CAMERA)
    assert isinstance(result, vantage.DesignSensorResult)
    assert result.complete and result.status == "complete"
    assert_same(result.to_dict(), cli_json(
        "design", patch_file, "--add", "2", "--objective", "camera", "--distance", "2",
        "--focal", "1000", "--noise-px", "0.3", "--crb-samples", "400"))
    assert result.augmented is not None
    assert result.augmented.entries.shape == (6, 3)
    report = vantage.analyze(result.augmented)
    assert report.sensor is not None
    assert report.sensor["value_deg"] == result.value
    assert result.initial is not None and result.value < result.initial["value_deg"]


def test_tracker_design_adds_the_candidates_the_cli_adds(vantage, patch_file):
    tracker = {"targets": [0, 0, -0.3], "fle_rms": 0.001}
    result = vantage.design(patch_file, add=2, objective="tracker", **tracker)
    cli = cli_json("design", patch_file, "--add", "2", "--objective", "tracker",
                   "--target", "0,0,-0.3", "--fle-rms", "0.001")
    assert_same(result.to_dict(), cli)
    np.testing.assert_array_equal(result.added, cli["added"])


@pytest.mark.parametrize("kwargs, field", [
    ({"objective": "camera", "distance": 2.0, "noise_px": 0.3}, "focal"),
    ({"objective": "camera", "margin": 1.0, **CAMERA}, "margin"),
    ({"objective": "tracker", "targets": [0, 0, 1]}, "fle_rms"),
    ({"focal": 1000.0}, "focal"),
    ({"objective": "camera", "add": 7, **CAMERA}, "add"),
    ({"objective": "camera", **{**CAMERA, "distance": 0.01}}, "distance"),
    ({"objective": "camera", "min_distance_difference": -0.1, **CAMERA}, "min_distance_difference"),
])
def test_bad_settings_name_the_keyword(vantage, patch_file, kwargs, field):
    kwargs = {"add": 1, **kwargs}
    with pytest.raises(ValueError) as error:
        vantage.design(patch_file, **kwargs)
    assert error.value.field == field, str(error.value)


def test_a_layout_without_candidates_is_refused(vantage):
    with pytest.raises(ValueError) as error:
        vantage.design(points=MARKERS, add=1, objective="camera", **CAMERA)
    assert error.value.field == "candidates"
