"""vantage.design(min_distance_difference=D) (docs/math.md §24, ART's identification rule): the
same report as `vantage design --min-distance-difference D --json`, a final layout whose every
two inter-marker distances differ by D or more (brute force here), and a bad D raising
ValueError naming the argument."""

import itertools
import math

import numpy as np
import pytest

from conftest import LAYOUTS, assert_same, cli_json

# Distances recomputed here from the layout's coordinates agree with the library's to rounding.
BRUTE = 1e-12


def brute_distance_difference(points):
    """min |d_ij - d_kl| over distinct pairs {i, j} != {k, l} (Eq. 24.1), by enumeration."""
    lengths = [np.linalg.norm(points[i] - points[j])
               for i, j in itertools.combinations(range(len(points)), 2)]
    return min(abs(x - y) for x, y in itertools.combinations(lengths, 2))


# Four markers whose six distances differ by 0.0296 or more; the free design's fifth marker
# brings two distances within 0.0144 of each other, so a D of 0.9 of the tool's own margin binds.
SPREAD_TOOL = [[0, 0, 0], [1.0, 0, 0], [0.2, 1.3, 0], [0.3, 0.4, 0.9]]


def test_design_keeps_the_distance_difference(vantage, tmp_path):
    path = str(tmp_path / "tool.json")
    vantage.save_layout(vantage.Layout(points=SPREAD_TOOL, name="spread"), path)
    gap = 0.9 * brute_distance_difference(np.asarray(SPREAD_TOOL, dtype=np.float64))
    free = vantage.design(path, add=1, direct=False)
    assert free.augmented is not None
    assert brute_distance_difference(free.augmented.entries) < gap  # the constraint binds
    result = vantage.design(path, add=1, direct=False, min_distance_difference=gap)
    cli = cli_json("design", path, "--add", 1, "--no-direct", "--min-distance-difference",
                   repr(gap))
    assert_same(result.to_dict(), cli)
    assert result.min_distance_difference == gap
    assert result.augmented is not None and len(result.augmented) == len(SPREAD_TOOL) + 1
    achieved = brute_distance_difference(result.augmented.entries)
    assert achieved >= gap
    assert result.final_distance_difference is not None
    assert abs(result.final_distance_difference - achieved) <= BRUTE


def test_design_without_the_constraint_reports_zero(vantage):
    result = vantage.design(points=SPREAD_TOOL, add=1, direct=False)
    assert result.min_distance_difference == 0.0
    assert result.augmented is not None and result.final_distance_difference is not None
    assert abs(result.final_distance_difference -
               brute_distance_difference(result.augmented.entries)) <= BRUTE


@pytest.mark.parametrize("gap", [-0.01, math.inf, math.nan])
def test_design_bad_distance_difference_raises(vantage, gap):
    with pytest.raises(ValueError) as error:
        vantage.design(points=SPREAD_TOOL, add=1, direct=False, min_distance_difference=gap)
    assert error.value.field == "min_distance_difference"


def test_design_distance_difference_the_layout_breaks_raises(vantage):
    path = str(LAYOUTS / "drone.json")
    own = brute_distance_difference(vantage.load_layout(path).entries)
    with pytest.raises(ValueError) as error:
        vantage.design(path, add=1, direct=False, min_distance_difference=2.0 * own)
    assert error.value.field == "min_distance_difference"
    assert error.value.source == path
