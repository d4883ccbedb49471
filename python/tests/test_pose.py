"""pose and orient: every estimator against `vantage pose --json` on the example
correspondences; shapes and exceptions."""

import json
import re

import numpy as np
import pytest

from conftest import CORRESPONDENCES, assert_same, cli_error, cli_json, run_cli

# (file, method, extra CLI flags, extra keyword arguments)
CASES = [
    ("affine_pose.json", "affine", [], {}),
    ("affine_pose.json", "standard", [], {}),
    ("affine_pose.json", "full3d", [], {}),
    ("affine_pose.json", "affine", ["--focal", "800"], {"focal": 800}),
    ("affine_pose.json", "affine", ["--free-vectors", "spanning"], {"free_vectors": "spanning"}),
    ("affine_pose.json", "affine", ["--free-vectors", "all"], {"free_vectors": "all"}),
    ("affine_pose.json", "affine", ["--principal-point", "3", "-2"], {"principal_point": [3, -2]}),
    ("affine_pose.json", "affine-refined", [], {}),
    ("affine_pose.json", "affine-refined", ["--focal", "800"], {"focal": 800}),
    ("perspective_pose.json", "perspective", [], {}),
    ("perspective_pose.json", "perspective", ["--free-vectors", "spanning"],
     {"free_vectors": "spanning"}),
    ("cube.json", "full3d", [], {}),
    ("perspective_pose.json", "oi-foam", [], {}),
    ("perspective_pose.json", "oi-svd", [], {}),
    ("two_view.json", "two-view", [], {}),
]


def test_python_binds_exactly_the_cli_methods(vantage):
    out, _ = run_cli("pose", "--help")
    cli_methods = re.search(r"--method TEXT:\{([^}]*)\}", out).group(1).split(",")
    assert sorted(vantage.pose_methods()) == sorted(cli_methods)


@pytest.mark.parametrize("name, method, flags, kwargs", CASES)
def test_pose_matches_the_cli(vantage, name, method, flags, kwargs):
    path = CORRESPONDENCES / name
    data = vantage.load_correspondences(path)
    result = vantage.pose(**{**data, **kwargs}, method=method)
    assert_same(result.to_dict(), cli_json("pose", path, "--method", method, *flags))
    assert result.R.shape == (3, 3)


def test_camera_of_the_file_reaches_vantage_pose(vantage, tmp_path):
    # perspective_pose.json in pixels of a camera with f = 800, c = (320, 240): the file's camera
    # is read by load_correspondences, the pose is the stated truth and equals the CLI's.
    source = json.loads((CORRESPONDENCES / "perspective_pose.json").read_text())
    focal, centre = 800.0, [320.0, 240.0]
    source["image"] = [[focal * x + centre[0], focal * y + centre[1]] for x, y in source["image"]]
    source["camera"] = {"focal": focal, "principal_point": centre}
    path = tmp_path / "pixels.json"
    path.write_text(json.dumps(source))
    data = vantage.load_correspondences(path)
    assert data["focal"] == focal
    np.testing.assert_array_equal(data["principal_point"], centre)
    result = vantage.pose(**data, method="perspective")
    assert_same(result.to_dict(), cli_json("pose", path, "--method", "perspective"))
    np.testing.assert_allclose(result.p, [0.15, -0.1, 4.0], atol=1e-9)


@pytest.mark.parametrize("method", ["qmethod", "svd", "foam"])
def test_orient_matches_the_cli(vantage, method):
    path = CORRESPONDENCES / "cube.json"
    data = vantage.load_correspondences(path)
    result = vantage.orient(data["model"], data["measured"], weights=data["weights"],
                            method=method)
    assert_same(result.to_dict(), cli_json("orient", path, "--method", method))


def test_orient_recovers_a_known_similarity(vantage):
    rng = np.random.default_rng(20061122)
    model = rng.normal(size=(6, 3)).astype(np.float32)  # float32 input is converted exactly
    angle = 0.7
    R = np.array([[np.cos(angle), -np.sin(angle), 0], [np.sin(angle), np.cos(angle), 0],
                  [0, 0, 1]])
    p = np.array([0.3, -1.0, 4.0])
    alpha = 2.0
    measured = (model.astype(float) @ R.T + p) / alpha  # alpha * measured = R * model + p
    result = vantage.orient(model, measured)
    np.testing.assert_allclose(result.R, R, atol=1e-12)
    np.testing.assert_allclose(result.p, p, atol=1e-12)
    assert result.alpha == pytest.approx(alpha, rel=1e-12)


def test_pose_input_errors(vantage):
    data = vantage.load_correspondences(CORRESPONDENCES / "affine_pose.json")
    with pytest.raises(ValueError, match=r"image: missing, required by the affine method"):
        vantage.pose(data["model"], method="affine")
    with pytest.raises(ValueError, match="method: unknown pose method \"dlt\""):
        vantage.pose(data["model"], data["image"], method="dlt")
    with pytest.raises(ValueError, match=r"image: expected an n x 2 array .* pass image.T"):
        vantage.pose(data["model"], data["image"].T)
    for focal in (-1, float("nan"), "800"):
        with pytest.raises(ValueError, match="focal: must be a finite number > 0"):
            vantage.pose(data["model"], data["image"], focal=focal)
    with pytest.raises(ValueError, match="free_vectors: only affine, affine-refined, perspective"):
        vantage.pose(data["model"], data["image"], method="oi-foam", free_vectors="all")
    with pytest.raises(ValueError, match="free_vectors: expected auto, all or spanning"):
        vantage.pose(data["model"], data["image"], free_vectors="tree")
    with pytest.raises(ValueError, match="principal_point: must be two finite numbers"):
        vantage.pose(data["model"], data["image"], principal_point=[1, float("nan")])
    with pytest.raises(ValueError, match="principal_point: not used by method='full3d'"):
        vantage.pose(data["model"], measured=data["model"], method="full3d",
                     principal_point=[0, 0])


def test_correspondence_file_errors_are_the_cli_message(vantage, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "bad.json").write_text('{"model": [[0, 0, 0], [1, 0]]}')
    with pytest.raises(ValueError) as error:
        vantage.load_correspondences("bad.json")
    assert str(error.value) == cli_error("orient", "bad.json")


def test_degenerate_orientation_raises_numerical_error_with_status(vantage):
    model = np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0]], dtype=float)  # collinear
    with pytest.raises(vantage.NumericalError) as error:
        vantage.orient(model, model)
    assert error.value.status == "degenerate"
    assert error.value.result.status == "degenerate"
    assert error.value.result.R.shape == (3, 3)
