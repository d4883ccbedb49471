"""vantage.ident (docs/math.md §24, Eq. 24.4): the typed result carries exactly the fields of
`vantage ident --json` on the example tools, every pair's mismatch equals a brute force over
subsets and labellings written here, and bad input raises ValueError naming the argument."""

import itertools
import json
import math

import numpy as np
import pytest

from conftest import SOURCE, assert_same, cli_json

TOOLS = SOURCE / "examples" / "tools"
TOOL_FILES = sorted(str(p) for p in TOOLS.iterdir() if p.suffix in (".json", ".ini"))
JSON_TOOLS = sorted(str(p) for p in TOOLS.glob("*.json"))
# The brief's tolerance: distances recomputed here from the files' coordinates agree with the
# library's to a few roundings of numbers below 10^3.
BRUTE = 1e-12


def tool_points(path):
    return np.asarray(json.loads(open(path).read())["points"], dtype=np.float64)


def brute_mismatch(a, b, k, same):
    """Eq. (24.4) by enumeration: the least, over k-subsets S of A's markers and injective
    labellings sigma: S -> B (for A against itself, sigma other than the identity), of the
    largest |d^A_ij - d^B_sigma(i)sigma(j)|."""
    da = np.linalg.norm(a[:, None, :] - a[None, :, :], axis=2)
    db = np.linalg.norm(b[:, None, :] - b[None, :, :], axis=2)
    best = math.inf
    for subset in itertools.combinations(range(len(a)), k):
        for sigma in itertools.permutations(range(len(b)), k):
            if same and sigma == subset:
                continue
            worst = max(abs(da[subset[i], subset[j]] - db[sigma[i], sigma[j]])
                        for i, j in itertools.combinations(range(k), 2))
            best = min(best, worst)
    return best


@pytest.mark.parametrize("min_visible", [3, 4])
def test_ident_is_the_cli_report(vantage, min_visible):
    report = vantage.ident(TOOL_FILES, min_visible=min_visible)
    cli = cli_json("ident", *TOOL_FILES, "--min-visible", min_visible)
    assert_same(report.to_dict(), cli)
    assert isinstance(report, vantage.IdentReport)
    assert report.min_visible == min_visible and report.certified == cli["certified"]
    assert [t.file for t in report.tools] == TOOL_FILES
    assert all(isinstance(t, vantage.IdentTool) for t in report.tools)
    n = len(TOOL_FILES)
    assert len(report.pairs) == n * (n + 1) // 2
    for pair, fields in zip(report.pairs, cli["pairs"]):
        assert isinstance(pair, vantage.IdentPair)
        assert (pair.a, pair.b, pair.self) == (fields["a"], fields["b"], fields["a"] == fields["b"])
        assert pair.mismatch == fields["mismatch"]
        assert list(pair.subset) == fields["subset"]
        assert list(pair.assignment) == fields["assignment"]
        assert pair.subset_names == fields["subset_names"]
        assert pair.transform == fields["transform"]
        assert pair.comparisons == fields["comparisons"]
    closest = cli["closest"]
    assert (report.closest.a, report.closest.b) == (closest["a"], closest["b"])
    assert report.closest.mismatch == closest["mismatch"]
    assert report.closest.mismatch == min(p.mismatch for p in report.pairs)


def test_ident_of_layouts_is_the_report_of_their_files(vantage):
    layouts = [vantage.load_layout(path) for path in JSON_TOOLS]
    from_layouts = vantage.ident(layouts).to_dict()
    from_files = vantage.ident(JSON_TOOLS).to_dict()
    assert [t["file"] for t in from_layouts["tools"]] == [None] * len(JSON_TOOLS)
    for tool in from_files["tools"]:
        tool["file"] = None
    assert from_layouts == from_files


def test_ident_of_a_folder_is_the_clis_with_verdicts_and_matrix(vantage):
    report = vantage.ident([TOOLS])
    cli = cli_json("ident", TOOLS)
    assert_same(report.to_dict(), cli)
    assert [t.file for t in report.tools] == sorted(
        str(p) for p in TOOLS.iterdir() if p.suffix in (".json", ".csv", ".ini", ".rom"))
    n = len(report.tools)
    assert report.matrix.shape == (n, n)
    for pair in report.pairs:
        assert report.matrix[pair.a, pair.b] == report.matrix[pair.b, pair.a] == pair.mismatch
        assert pair.verdict == ("self" if pair.self else "distinct")
        assert pair.min_visible == min(report.tools[pair.a].min_visible,
                                       report.tools[pair.b].min_visible)
    assert report.closest_distinct is not None and not report.closest_distinct.self
    assert report.closest_distinct.mismatch == min(p.mismatch for p in report.pairs if not p.self)


@pytest.mark.parametrize("min_visible", [3, 4])
def test_ident_mismatch_is_the_brute_force(vantage, min_visible):
    points = [tool_points(path) for path in JSON_TOOLS]
    report = vantage.ident(JSON_TOOLS, min_visible=min_visible)
    assert report.certified
    for pair in report.pairs:
        a, b = points[pair.a], points[pair.b]
        truth = brute_mismatch(a, b, min_visible, pair.self)
        assert abs(pair.mismatch - truth) <= BRUTE, (pair.a, pair.b)
        # The reported markers give the reported mismatch.
        da = np.linalg.norm(a[pair.subset][:, None] - a[pair.subset][None], axis=2)
        db = np.linalg.norm(b[pair.assignment][:, None] - b[pair.assignment][None], axis=2)
        assert abs(np.max(np.abs(da - db)) - pair.mismatch) <= BRUTE


@pytest.mark.parametrize("call, field, index", [
    (lambda v: v.ident(JSON_TOOLS, min_visible=2), "min_visible", None),
    (lambda v: v.ident(JSON_TOOLS, same_tolerance=-1.0), "same_tolerance", None),
    (lambda v: v.ident(JSON_TOOLS, min_visible=3.5), "min_visible", None),
    (lambda v: v.ident(JSON_TOOLS, min_visible=5), "min_visible", None),
    (lambda v: v.ident([v.Layout(points=np.eye(3))], min_visible=4), "min_visible", None),
    (lambda v: v.ident([]), "tools", None),
    (lambda v: v.ident(JSON_TOOLS[0]), "tools", None),
    (lambda v: v.ident(3), "tools", None),
    (lambda v: v.ident([JSON_TOOLS[0], 3]), "tools", 1),
    (lambda v: v.ident([v.Layout(vectors=np.eye(3))]), "tools", 0),
    (lambda v: v.ident([TOOLS, v.Layout(vectors=np.eye(3))]), "tools", 1),
    (lambda v: v.ident([JSON_TOOLS[0], SOURCE / "docs"]), "tools", 1),
])
def test_ident_bad_input_raises_naming_the_argument(vantage, call, field, index):
    with pytest.raises(ValueError) as error:
        call(vantage)
    assert error.value.field == field, str(error.value)
    assert error.value.index == index, str(error.value)


def test_ident_takes_any_iterable_of_tools(vantage):
    assert vantage.ident(iter(JSON_TOOLS)) == vantage.ident(JSON_TOOLS)
