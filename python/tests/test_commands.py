"""analyze, design and weights: the same numbers as the CLI's --json, from files and arrays;
exceptions; the GIL is released during the computation."""

import os
import pathlib
import threading
import time

import numpy as np
import pytest

from conftest import LAYOUTS, EXAMPLE_LAYOUTS, assert_same, cli_json


@pytest.mark.parametrize("name", EXAMPLE_LAYOUTS)
def test_analyze_matches_the_cli_on_every_example(vantage, name):
    path = str(LAYOUTS / name)
    assert_same(vantage.analyze(path).to_dict(), cli_json("analyze", path))


def test_analyze_options_match_the_cli(vantage):
    path = str(LAYOUTS / "apriltag_cube.yaml")
    result = vantage.analyze(path, tag_points="centres", swaps=2, crosscheck=False,
                             pair_weighting="arithmetic")
    assert_same(result.to_dict(),
                cli_json("analyze", path, "--tag-points", "centres", "--swaps", "2",
                         "--no-crosscheck", "--pair-weighting", "arithmetic"))


def test_analyze_result_attributes_are_the_json_fields_as_numpy(vantage):
    result = vantage.analyze(vectors=np.eye(3))
    assert result.pbar_min == pytest.approx(np.sqrt(2 / 3), abs=1e-9)
    assert result.worst_viewpoints.shape == (4, 3)
    assert result.worst_case_errors_deg.shape == (3,)
    assert result.certificate.certified is True
    assert result.solver.backend == "csdp"
    assert isinstance(result.swaps[0].error_deg, float)
    points = vantage.analyze(points=[[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]])
    assert points.swaps[0].pair_i.dtype.kind == "i"  # marker indices stay integers
    # Every field of the JSON is a typed attribute (message only when not usable).
    missing = [key for key in result.to_dict() if not hasattr(result, key)]
    assert missing == []
    assert result.message is None and result.dropout is None
    assert isinstance(result.certificate, vantage.Certificate)
    assert isinstance(result.swaps[0], vantage.Swap)


def test_arrays_and_files_give_the_same_analysis(vantage):
    layout = vantage.load_layout(LAYOUTS / "satellite.json")
    from_points = vantage.analyze(points=layout.entries, weights=layout.weights).to_dict()
    from_layout = vantage.analyze(layout).to_dict()
    from_float32 = vantage.analyze(points=layout.entries.astype(np.float32)).to_dict()
    from_points.pop("name"), from_layout.pop("name")
    # The file's normals and body add "visibility" and "mesh"; the top-level fields (the layout
    # seen whole) are those of its points alone.
    assert from_layout.pop("visibility")["model"] == "cone+mesh"
    assert from_layout.pop("mesh")["triangles"] > 0
    assert_same(from_points, from_layout)
    assert from_float32["pbar_min"] == pytest.approx(from_layout["pbar_min"], abs=1e-6)


def test_design_matches_the_cli_and_its_layout_reanalyses(vantage, tmp_path):
    path = str(LAYOUTS / "triad.json")
    result = vantage.design(path, add=2, direct=False)
    cli = cli_json("design", path, "--add", "2", "--no-direct", "--write", tmp_path / "cli.json")
    assert cli.pop("written") == str(tmp_path / "cli.json")
    assert_same(result.to_dict(), cli)
    assert len(result.augmented) == 5
    vantage.save_layout(result.augmented, tmp_path / "python.json")
    assert (tmp_path / "python.json").read_text() == (tmp_path / "cli.json").read_text()
    final = vantage.analyze(result.augmented)
    assert final.pbar_min == pytest.approx(result.final_pbar_min, abs=1e-9)


def test_design_of_a_body_layout_warns_that_it_searches_seen_whole(vantage):
    # Issue 36, item 5: the CLI's warning line, as a RuntimeWarning.
    with pytest.warns(RuntimeWarning, match="does not use"):
        vantage.design(str(LAYOUTS / "drone.json"), add=1, direct=False)


@pytest.mark.parametrize("name", ["triad.json", "satellite.json", "mocap_rigid_body.csv",
                                  "apriltag_cube.yaml", "coplanar_fan.json"])
def test_weights_match_the_cli(vantage, name):
    path = str(LAYOUTS / name)
    assert_same(vantage.weights(path).to_dict(), cli_json("weights", path))


@pytest.mark.parametrize("call, expected", [
    (lambda v: v.analyze(vectors=np.eye(3), swaps=0), "swaps: must be >= 1"),
    (lambda v: v.analyze(vectors=np.eye(3), pair_weighting="median"), "pair_weighting"),
    (lambda v: v.analyze(np.eye(3)), "layout: expected a str or os.PathLike"),
    (lambda v: v.analyze(123), "layout: expected a str or os.PathLike"),
    (lambda v: v.analyze(str(LAYOUTS / "triad.json"), vectors=np.eye(3)), "not both"),
    (lambda v: v.design(vectors=np.eye(3), add=0), "add: must be >= 1"),
    (lambda v: v.design(vectors=np.eye(3), margin=-1), "margin"),
    (lambda v: v.weights(vectors=[[1, 0, 0]]), "vectors: need at least 2"),
])
def test_bad_arguments_raise_value_error(vantage, call, expected):
    with pytest.raises(ValueError) as error:
        call(vantage)
    assert expected in str(error.value)


def test_design_refuses_what_the_library_refuses_by_keyword(vantage):
    # The library's rules reach Python as they reach the CLI (issue 34, item 4): a candidate on a
    # marker, checked only by the CLI before, and options named by their keywords.
    points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
    with pytest.raises(ValueError) as error:
        vantage.design(points=points, candidates=[[1, 1, 1], [1, 0, 0]], add=1,
                       candidates_only=True, direct=False)
    assert error.value.field == "candidates" and error.value.index == 1
    assert str(error.value) == "candidates[1]: coincides with points[1]"
    for keyword, value in (("margin", 1e8), ("margin", -1.0), ("min_distance_difference", -0.1)):
        with pytest.raises(ValueError) as error:
            vantage.design(points=points, add=1, direct=False, **{keyword: value})
        assert error.value.field == keyword, str(error.value)


def test_design_without_enough_candidates_raises_numerical_error(vantage):
    layout = vantage.Layout(vectors=np.eye(3), candidates=[[1, 1, 0]])
    with pytest.raises(vantage.NumericalError) as error:
        vantage.design(layout, add=2, candidates_only=True, direct=False)
    assert error.value.status == "no_candidates"
    assert error.value.result.status == "no_candidates"
    assert len(error.value.result.steps) == 1
    assert isinstance(error.value.result, vantage.DesignResult)
    assert isinstance(error.value, RuntimeError)


def test_the_gil_is_released_while_analysing(vantage):
    # 3000 random directions: long enough to observe (about 0.1 s here), seeded.
    vectors = np.random.default_rng(20061122).normal(size=(3000, 3))
    span = {}

    def work():
        span["start"] = time.perf_counter()
        vantage.analyze(vectors=vectors)
        span["end"] = time.perf_counter()

    worker = threading.Thread(target=work)
    ticks = []
    worker.start()
    while worker.is_alive():
        ticks.append(time.perf_counter())
        time.sleep(0.001)
    worker.join()
    start, end = span["start"], span["end"]
    middle = [t for t in ticks if start + 0.25 * (end - start) < t < start + 0.75 * (end - start)]
    # With the GIL held for the whole C++ call the main thread could not run in between.
    assert end - start > 0.02, "the analysis is too short to tell"
    assert middle, f"no Python ran during the {end - start:.3f} s analysis"


def test_concurrent_analyses_agree_with_a_serial_one(vantage):
    from concurrent.futures import ThreadPoolExecutor
    path = str(LAYOUTS / "note3_four_vectors.json")
    serial = vantage.analyze(path).to_dict()
    with ThreadPoolExecutor(max_workers=3) as pool:
        results = list(pool.map(lambda _: vantage.analyze(path).to_dict(), range(3)))
    for result in results:
        assert_same(result, serial)


def test_a_file_name_that_is_not_utf8_is_read(vantage, tmp_path):
    # Issue 36, item 8 (review): os.fsdecode gives such a name surrogate escapes, which could not
    # be cast to the C++ string ("Unable to cast"); the file system's bytes are passed instead.
    original = LAYOUTS / "triad.json"
    name = os.path.join(os.fsencode(tmp_path), b"\xff-triad.json")
    with open(name, "wb") as out:
        out.write(original.read_bytes())
    expected = vantage.analyze(str(original)).to_dict()
    for path in (name, os.fsdecode(name), pathlib.Path(os.fsdecode(name))):
        result = vantage.analyze(path).to_dict()
        assert result["worst_viewpoint"] == expected["worst_viewpoint"]
        assert result["pbar_min"] == expected["pbar_min"]
