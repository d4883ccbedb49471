"""Layouts on their bodies (normals, cones, a mesh; docs/math.md §20): analyze() and simulate()
expose the "visibility" objects of the CLI's --json as typed attributes, with the same numbers,
and the loader reads normals, visibility and workspace as the JSON file gives them."""

import json

import numpy as np
import pytest

from conftest import LAYOUTS, assert_same, cli_json
from test_simulate import without_times

SATELLITE = str(LAYOUTS / "satellite.json")
# A unit vector's dot product with a unit axis, rounded in a few operations.
DOT_ROUNDING = 1e-12


def test_analyze_exposes_the_visibility_report_of_the_cli(vantage):
    result = vantage.analyze(SATELLITE)
    cli = cli_json("analyze", SATELLITE)
    assert_same(result.to_dict()["visibility"], cli["visibility"])
    v = result.visibility
    assert isinstance(v, vantage.LayoutVisibility)
    c = cli["visibility"]
    assert v.model == c["model"] == "cone+mesh"
    assert v.min_visible == c["min_visible"]
    assert v.workspace is None and c["workspace"] is None
    assert v.trackable_fraction == c["trackable_fraction"]
    assert v.t == c["t"] and v.pbar_min == c["pbar_min"]
    assert v.max_worst_case_error_deg == c["max_worst_case_error_deg"]
    np.testing.assert_array_equal(v.worst_viewpoint, c["worst_viewpoint"])
    np.testing.assert_array_equal(v.worst_viewpoints, c["worst_viewpoints"])
    np.testing.assert_array_equal(v.visible_markers, c["visible_markers"])
    assert v.certificate.t_upper == c["certificate"]["t_upper"]
    assert v.certificate.t_lower == c["certificate"]["t_lower"]
    # On a body the certificate holds on the occlusion grid, not under exact rays.
    assert v.certificate.certified is c["certificate"]["certified"] is False
    assert v.certificate.certified_at_resolution is True
    assert v.status == c["status"] == "certified_at_resolution"
    assert v.exact_viewpoint is not None and v.exact_viewpoint.agrees
    np.testing.assert_array_equal(v.exact_viewpoint.visible_markers, v.visible_markers)
    assert v.occlusion_resolution_deg == c["occlusion_resolution_deg"]
    assert v.lost.fraction == c["lost"]["fraction"]
    np.testing.assert_array_equal(v.lost.largest_region_center,
                                  c["lost"]["largest_region_center"])
    np.testing.assert_array_equal(v.distance_to_body, c["distance_to_body"])
    assert v.to_dict() == c


def test_a_layout_without_normals_has_no_visibility(vantage):
    result = vantage.analyze(str(LAYOUTS / "triad.json"))
    assert result.visibility is None
    assert "visibility" not in result.to_dict()


def test_simulate_exposes_the_check_under_visibility_of_the_cli(vantage):
    result = vantage.simulate(SATELLITE, trials=80, seed=3, noise_px=0.5, threads=2,
                              per_trial=True)
    cli = cli_json("simulate", SATELLITE, "--trials", "80", "--seed", "3", "--noise-px", "0.5",
                   "--threads", "2", "--per-trial", "--quiet")
    assert_same(without_times(result.to_dict()), without_times(cli))
    v = result.visibility
    c = cli["visibility"]
    assert isinstance(v, vantage.SimulationVisibility)
    assert v.model == "cone+mesh" and v.bound_checked and v.passed
    assert v.trials == 80 and v.draws == c["draws"] >= 80
    assert v.pbar_min == c["pbar_min"] and v.bound_deg == c["bound_deg"]
    assert v.max_error_deg == c["max_error_deg"] and v.max_ratio == c["max_ratio"]
    assert v.max_view_t == c["max_view_t"] <= v.t_upper
    assert v.visible_markers.median == c["visible_markers"]["median"]
    np.testing.assert_array_equal(v.worst_viewpoint, c["worst_viewpoint"])
    # The certified worst viewpoint of simulate is analyze's.
    assert v.t_upper == vantage.analyze(SATELLITE).visibility.certificate.t_upper


def test_the_loader_reads_normals_visibility_and_workspace_as_the_json_does(vantage, tmp_path):
    spec = json.loads((LAYOUTS / "satellite.json").read_text())
    spec["visibility"].pop("body")  # the mesh path is relative to the original file
    spec["workspace"] = {"axis": [0, 0, 2], "half_angle_deg": 60}
    path = tmp_path / "docked.json"
    path.write_text(json.dumps(spec))
    result = vantage.analyze(str(path))
    cli = cli_json("analyze", str(path))
    assert_same(result.to_dict()["visibility"], cli["visibility"])
    v = result.visibility
    assert v.model == "cone"
    np.testing.assert_array_equal(v.workspace.axis, [0.0, 0.0, 1.0])  # normalised on reading
    assert v.workspace.half_angle_deg == 60.0
    assert v.worst_viewpoint @ v.workspace.axis >= np.cos(np.radians(60.0)) - DOT_ROUNDING


def test_a_layout_built_in_python_on_its_body_is_the_files(vantage):
    spec = json.loads((LAYOUTS / "docking_target.json").read_text())
    built = vantage.Layout(points=np.array(spec["points"]), normals=np.array(spec["normals"]),
                           visibility=spec["visibility"], workspace=spec["workspace"])
    loaded = vantage.load_layout(str(LAYOUTS / "docking_target.json"))
    np.testing.assert_array_equal(built.normals, loaded.normals)
    assert_same(vantage.analyze(built).to_dict()["visibility"],
                vantage.analyze(loaded).to_dict()["visibility"])
    assert vantage.Layout(points=np.array(spec["points"])).normals is None
    with pytest.raises(ValueError, match="visibility.min_visible"):
        vantage.Layout(points=np.array(spec["points"]), normals=np.array(spec["normals"]),
                       visibility={"min_visible": 2})
    with pytest.raises(ValueError, match="normals"):
        vantage.Layout(points=np.array(spec["points"]), visibility={"min_visible": 3})


def test_an_answer_exact_rays_contradict_raises_with_that_status(vantage, tmp_path):
    # Issue 36, item 3: markers on opposite faces of a box, all four needed: the occlusion grid
    # makes a sliver that the exact rays at its viewpoint do not see (docs/math.md §20).
    (tmp_path / "box.obj").write_text(
        "v -0.5 -0.5 -0.5\nv -0.5 -0.5 0.5\nv -0.5 0.5 -0.5\nv -0.5 0.5 0.5\n"
        "v 0.5 -0.5 -0.5\nv 0.5 -0.5 0.5\nv 0.5 0.5 -0.5\nv 0.5 0.5 0.5\n"
        "f 1 2 4 3\nf 5 7 8 6\nf 1 5 6 2\nf 3 4 8 7\nf 1 3 7 5\nf 2 6 8 4\n")
    layout = tmp_path / "opposite.json"
    layout.write_text(
        '{"points": [[0.5, 0.2, 0.1], [0.5, -0.2, -0.15], [-0.5, 0.25, -0.1], [-0.5, -0.1, 0.2]],'
        ' "normals": [[1, 0, 0], [1, 0, 0], [-1, 0, 0], [-1, 0, 0]],'
        ' "visibility": {"cone_half_angle_deg": 100, "min_visible": 4, "body": "box.obj"}}')
    with pytest.raises(vantage.NumericalError) as caught:
        vantage.analyze(str(layout))
    assert caught.value.status == "exact_rays_disagree"
    v = caught.value.result.visibility
    assert v.status == "not_certified" and not v.certificate.certified_at_resolution
    assert v.exact_viewpoint is not None and not v.exact_viewpoint.agrees
