"""The typed front end: real signatures (no *args/**kwargs), typed results whose to_dict() is
the CLI's --json and whose repr is the CLI's own report head, dropout=, the CLI's size limits
with allow_large=, and ValueError's field/index/problem."""

import inspect
import re

import numpy as np
import pytest

from conftest import CORRESPONDENCES, LAYOUTS, assert_same, cli_error, cli_json, run_cli

PUBLIC_CALLS = [
    "analyze", "design", "weights", "pose", "orient", "simulate", "tre", "ident", "place",
    "load_layout"]

# Seeded random unit directions for the size limits (any directions do: the limit counts them).
SEED = 17


def random_directions(count):
    vectors = np.random.default_rng(SEED).normal(size=(count, 3))
    return vectors / np.linalg.norm(vectors, axis=1, keepdims=True)


def extension_defaults(function):
    """The keyword defaults the compiled function declares (pybind11's signature line)."""
    line = function.__doc__.splitlines()[0]
    return dict(re.findall(r"(\w+): [\w.]+(?:\[[\w, .]+\])? = (\[[^\]]*\]|[^,)]+)", line))


@pytest.mark.parametrize("name", PUBLIC_CALLS)
def test_public_functions_have_real_signatures_and_docstrings(vantage, name):
    function = getattr(vantage, name)
    kinds = {p.kind for p in inspect.signature(function).parameters.values()}
    assert inspect.Parameter.VAR_KEYWORD not in kinds
    assert inspect.Parameter.VAR_POSITIONAL not in kinds
    assert function.__doc__ and len(function.__doc__) > 80


@pytest.mark.parametrize(
    "name", ["analyze", "design", "weights", "pose", "orient", "simulate", "tre", "ident", "place"])
def test_python_defaults_are_the_extensions_defaults(vantage, name):
    python = inspect.signature(getattr(vantage, name)).parameters
    compiled = extension_defaults(getattr(vantage._vantage, name))
    assert set(compiled) <= set(python), set(compiled) - set(python)
    for key, text in compiled.items():
        default = python[key].default
        if text == "None":
            assert default is None, key
        elif text.startswith("["):
            assert list(default) == eval(text), key  # noqa: S307 (a literal of the signature)
        elif text in ("True", "False"):
            assert default is (text == "True"), key
        elif text.startswith("'"):
            assert default == text.strip("'"), key
        else:
            assert default == pytest.approx(float(text), rel=0, abs=0), key


def test_the_report_is_typed_and_its_repr_is_the_cli_report_head(vantage):
    path = str(LAYOUTS / "satellite.json")
    report = vantage.analyze(path)
    assert isinstance(report, vantage.LayoutReport)
    assert report.worst_viewpoint.dtype == np.float64 and report.worst_viewpoint.shape == (3,)
    assert report.worst_viewpoints.shape[1] == 3
    assert isinstance(report.crosscheck, vantage.Crosscheck) and report.crosscheck.ran
    assert isinstance(report.coplanarity.normal, np.ndarray)
    text, _ = run_cli("analyze", path)
    # On its body (the satellite has normals) the report leads with the visibility part.
    assert repr(report) in text and repr(report).startswith("on its body")
    assert report.brief_report().rstrip("\n") == repr(report)
    seen_whole = vantage.analyze(str(LAYOUTS / "triad.json"))
    text, _ = run_cli("analyze", str(LAYOUTS / "triad.json"))
    assert repr(seen_whole) in text and repr(seen_whole).startswith("pbar_min")


def test_dropout_matches_the_cli(vantage):
    path = str(LAYOUTS / "satellite.json")
    report = vantage.analyze(path, dropout=True)
    assert_same(report.to_dict(), cli_json("analyze", path, "--dropout"))
    assert report.dropout is not None and len(report.dropout) == 12
    for k, entry in enumerate(report.dropout):
        assert entry.index == k and entry.certified
        # Removing a marker cannot raise p-bar_min (the minimum is over fewer vectors, so the
        # worst viewpoint's figure can only grow: fewer constraints on max_a min_i |a.n_i|).
        assert entry.pbar_min <= report.pbar_min + 1e-12


def test_pose_is_typed_with_its_diagnostics(vantage):
    data = vantage.load_correspondences(CORRESPONDENCES / "affine_pose.json")
    estimate = vantage.pose(**data)
    assert isinstance(estimate, vantage.PoseEstimate)
    assert estimate.R.shape == (3, 3) and estimate.p.shape == (3,)
    assert np.isnan(estimate.p[2])  # affine: depth unknown, JSON null
    assert estimate.diagnostics["free_vector_count"] == 12
    assert "R" not in estimate.diagnostics and "camera" not in estimate.diagnostics
    assert isinstance(estimate.camera, vantage.PoseCamera)


def test_other_results_are_typed(vantage):
    path = str(LAYOUTS / "triad.json")
    assert isinstance(vantage.weights(path).suggestion, vantage.WeightsSuggestion)
    better = vantage.design(path, direct=False)
    assert isinstance(better.steps[0], vantage.DesignStep)
    assert isinstance(better.augmented, vantage.Layout) and len(better.augmented) == 4
    run = vantage.simulate(path, trials=50)
    assert isinstance(run.estimators["affine"].rot_err_deg, vantage.Statistic)
    assert run.bound_check is not None and run.bound_check.passed
    turned = vantage.orient(np.eye(3), np.eye(3))
    assert isinstance(turned, vantage.Orientation) and np.allclose(turned.R, np.eye(3))


def test_analyze_has_the_cli_limit_and_allow_large_lifts_it(vantage, tmp_path):
    vectors = random_directions(20001)
    with pytest.raises(ValueError) as refused:
        vantage.analyze(vectors=vectors)
    assert "20001 exceeds the limit of 20000 for vantage.analyze()" in str(refused.value)
    assert "allow_large=True lifts it" in str(refused.value)
    assert refused.value.field == "data vectors"
    path = tmp_path / "dirs.json"
    vantage.save_layout(vantage.Layout(vectors=vectors), path)
    assert "20001 exceeds the limit of 20000 for `vantage analyze`" in cli_error("analyze", path)
    lifted = vantage.analyze(vectors=vectors, allow_large=True, crosscheck=False, swaps=1)
    assert lifted.n_vectors == 20001


def test_dropout_has_the_cli_limit(vantage):
    with pytest.raises(ValueError, match="1001 exceeds the limit of 1000 .*allow_large=True"):
        vantage.analyze(vectors=random_directions(1001), dropout=True)


def test_trials_and_design_time_have_the_cli_limits(vantage):
    path = str(LAYOUTS / "triad.json")
    with pytest.raises(ValueError, match="trials: 10000001 exceeds the limit of 10000000"):
        vantage.simulate(path, trials=10_000_001)
    with pytest.raises(ValueError, match="trials with per_trial=True: 40001 exceeds"):
        vantage.simulate(path, trials=40_001, per_trial=True)
    # The drone-like 5 markers with 20 additions: the estimate (about 41 s) exceeds 30 s.
    markers = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]]
    with pytest.raises(ValueError) as refused:
        vantage.design(points=markers, add=20)
    assert str(refused.value).startswith("add=20 on 300 data vectors: about 41 s of CPU exceeds "
                                         "the budget of 30 s for vantage.design()")


def test_monte_carlo_sweep_and_tool_count_have_the_cli_limits(vantage, tmp_path):
    tool = LAYOUTS.parent / "tools" / "ndi_like.json"
    # Refused before any work, named by the keyword; allow_large=True lifts the bound.
    with pytest.raises(ValueError, match=r"^monte_carlo: 10000001 exceeds the limit of 10000000 "
                                         r"for vantage.tre\(\) \(allow_large=True lifts it\)$"):
        vantage.tre(tool, targets=[0, 0, -150], fle_rms=0.3, monte_carlo=10_000_001)
    with pytest.raises(ValueError, match=r"^sweep_distance: 1001 exceeds the limit of 1000"):
        vantage.crb(LAYOUTS / "apriltag_cube.yaml", distance=2, focal=900, noise_px=0.3,
                    sweep_distance=(1.0, 4.0, 1001))
    with pytest.raises(ValueError, match=r"^tools: 501 exceeds the limit of 500") as refused:
        vantage.ident([str(tmp_path / "never_read.json")] * 501)
    assert refused.value.field == "tools"
    lifted = vantage.tre(tool, targets=[0, 0, -150], fle_rms=0.3, monte_carlo=1000,
                         allow_large=True)
    assert lifted.targets[0].monte_carlo.trials == 1000


def test_value_errors_carry_field_index_and_problem(vantage):
    with pytest.raises(ValueError) as bad:
        vantage.analyze(vectors=np.eye(3), weights=[1.0, -1.0, 1.0])
    assert (bad.value.field, bad.value.index, bad.value.problem) == ("weights", 1, "must be > 0")
    assert bad.value.source is None
    assert str(bad.value) == "weights[1]: must be > 0"


def test_the_file_size_limit_is_the_clis_and_allow_large_lifts_it(vantage, tmp_path):
    # One byte over the 64 MiB of io::kMaxFileBytes: refused before parsing, as the CLI refuses.
    path = tmp_path / "big.json"
    with open(path, "wb") as out:
        out.truncate((64 << 20) + 1)
    with pytest.raises(ValueError, match=r"allow_large=True raises it to 1 GiB"):
        vantage.load_layout(path)
    assert "--allow-large raises it to 1 GiB" in cli_error("analyze", path)
    # Lifted, the file is read whole and refused for what it holds (NUL bytes), not its size.
    with pytest.raises(ValueError) as parsed:
        vantage.load_layout(path, allow_large=True)
    assert "1 GiB" not in str(parsed.value)
