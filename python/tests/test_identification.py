"""The identification block of vantage.analyze (docs/math.md §24): typed, equal to the CLI's
JSON, and every number equal to a brute force over the tool's points written here."""

import itertools
import json

import numpy as np

from conftest import LAYOUTS, SOURCE, assert_same, cli_json

TOOLS = SOURCE / "examples" / "tools"
# Distances recomputed here from the file's coordinates agree with the library's to rounding.
ROUNDING = 1e-10


def tool_points(name):
    return np.asarray(json.loads((TOOLS / name).read_text())["points"], dtype=np.float64)


def brute_difference(points, lost=None):
    lengths = [np.linalg.norm(points[i] - points[j])
               for i, j in itertools.combinations(range(len(points)), 2) if lost not in (i, j)]
    return min(abs(a - b) for a, b in itertools.combinations(lengths, 2))


def brute_mirror(points):
    centred = points - points.mean(axis=0)
    best = np.inf
    for pi in itertools.permutations(range(len(points))):
        target = centred[list(pi)]
        u, _, vt = np.linalg.svd(target.T @ centred)
        flip = -np.linalg.det(u @ vt)
        q = u @ np.diag([1.0, 1.0, flip]) @ vt
        best = min(best, np.sqrt(np.mean(np.sum((centred @ q.T - target) ** 2, axis=1))))
    return best


def test_identification_is_typed_and_equals_brute_force(vantage):
    path = TOOLS / "five_marker.json"
    report = vantage.analyze(str(path))
    ident = report.identification
    assert isinstance(ident, vantage.Identification)
    points = tool_points("five_marker.json")
    assert abs(ident.min_distance_difference - brute_difference(points)) < ROUNDING
    a, b = ident.pair_a, ident.pair_b
    gap = abs(np.linalg.norm(points[a[0]] - points[a[1]]) - np.linalg.norm(points[b[0]] - points[b[1]]))
    assert abs(gap - ident.min_distance_difference) < ROUNDING
    separation = min(np.linalg.norm(points[i] - points[j])
                     for i, j in itertools.combinations(range(len(points)), 2))
    assert abs(ident.min_marker_separation - separation) < ROUNDING
    assert [e.lost for e in ident.under_dropout] == list(range(len(points)))
    for entry in ident.under_dropout:
        assert isinstance(entry, vantage.DistanceDifference)
        assert abs(entry.min_distance_difference - brute_difference(points, entry.lost)) < ROUNDING
    assert ident.worst_under_dropout.min_distance_difference == min(
        e.min_distance_difference for e in ident.under_dropout)
    assert ident.mirror_certified and not ident.own_mirror
    assert abs(ident.mirror_rms - brute_mirror(points)) < 1e-8
    assert ident.mirror_assignment.dtype == np.int64
    assert_same(report.to_dict(), cli_json("analyze", path))


def test_planar_tool_is_its_own_mirror_and_directions_have_no_block(vantage):
    planar = vantage.analyze(str(TOOLS / "west_planar.json")).identification
    assert planar is not None and planar.own_mirror and planar.mirror_rms < 1e-9
    assert vantage.analyze(str(LAYOUTS / "triad.json")).identification is None
