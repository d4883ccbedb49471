"""Layouts: reading every format, the Layout class, array shapes and dtypes, errors, round trips,
calibration boards."""

import numpy as np
import pytest

from conftest import LAYOUTS, EXAMPLE_LAYOUTS, cli_error, cli_json, run_cli

TRIAD = np.eye(3)


@pytest.mark.parametrize("name", EXAMPLE_LAYOUTS)
def test_every_example_loads_and_round_trips(vantage, name, tmp_path):
    layout = vantage.load_layout(LAYOUTS / name)
    assert layout.entries.shape == (len(layout), 3)
    assert layout.weights.shape == (len(layout),)
    assert layout.mode in ("vectors", "points")
    vantage.save_layout(layout, tmp_path / "again.json")
    again = vantage.load_layout(str(tmp_path / "again.json"))
    assert again.name == layout.name
    assert again.mode == layout.mode
    np.testing.assert_array_equal(again.entries, layout.entries)
    np.testing.assert_array_equal(again.weights, layout.weights)
    np.testing.assert_array_equal(again.candidates, layout.candidates)
    assert again.to_dict() == layout.to_dict()


def test_layout_from_arrays_matches_the_file(vantage):
    from_file = vantage.load_layout(LAYOUTS / "triad.json")
    from_arrays = vantage.Layout(vectors=TRIAD, name=from_file.name)
    assert from_arrays.to_dict() == from_file.to_dict()
    assert repr(from_arrays).startswith("<vantage.Layout 'orthogonal triad")


def test_apriltag_options_choose_corners_or_centres(vantage):
    corners = vantage.load_layout(LAYOUTS / "apriltag_cube.yaml")
    centres = vantage.load_layout(LAYOUTS / "apriltag_cube.yaml", tag_points="centres")
    assert (len(corners), len(centres)) == (12, 3)
    np.testing.assert_allclose(centres.entries, [[0, 0, 0.05], [0.05, 0, 0], [0, 0.05, 0]])
    # Each tag's corners average to its centre.
    np.testing.assert_allclose(corners.entries.reshape(3, 4, 3).mean(axis=1), centres.entries,
                               atol=1e-12)


def test_float32_and_integer_input_give_the_float64_layout(vantage):
    points = np.array([[0, 0, 0], [0.1, 0, 0.2], [0, 0.3, 0], [0.05, 0.05, 0.4]])
    reference = vantage.Layout(points=points)
    as_float32 = vantage.Layout(points=points.astype(np.float32))
    np.testing.assert_array_equal(as_float32.entries, points.astype(np.float32).astype(float))
    integers = np.array([[0, 0, 0], [1, 0, 2], [0, 3, 0], [1, 1, 4]])
    as_int = vantage.Layout(points=integers.astype(np.int32))
    np.testing.assert_array_equal(as_int.entries, integers.astype(float))
    as_list = vantage.Layout(points=points.tolist())
    np.testing.assert_array_equal(as_list.entries, reference.entries)


@pytest.mark.parametrize("array, expected", [
    (np.ones((3, 5)), "points: expected an n x 3 array (one row per entry), got shape (3, 5); "
                      "pass points.T"),
    (np.ones((5, 2)), "points: expected an n x 3 array (one row per entry), got shape (5, 2)"),
    (np.ones(9), "points: expected an n x 3 array (one row per entry), got shape (9,)"),
    (np.array([["a", "b", "c"]] * 3), "points: expected an array of numbers, got dtype <U1"),
    ([[0, 0, 0], [1, 0]], "points: expected an array of numbers"),
])
def test_wrong_shapes_and_dtypes_are_rejected_clearly(vantage, array, expected):
    with pytest.raises(ValueError) as error:
        vantage.Layout(points=array)
    assert str(error.value) == expected


@pytest.mark.parametrize("kwargs, expected", [
    (dict(vectors=np.eye(3), points=np.eye(3)), "give exactly one of vectors= or points="),
    (dict(), "vectors/points: missing"),
    (dict(points=[[0, 0, 0], [1, 0, 0], [1, 0, 0]]), "points[2]: coincides with points[1]"),
    (dict(vectors=TRIAD, weights=[1, 0, 1]), "weights[1]: must be > 0"),
    (dict(vectors=[[1, 0, 0], [0, np.nan, 1]]), "vectors[1]"),
])
def test_bad_layouts_raise_value_error_naming_field_and_index(vantage, kwargs, expected):
    with pytest.raises(ValueError, match=None) as error:
        vantage.Layout(**kwargs)
    assert expected in str(error.value)


@pytest.mark.parametrize("name, text", [
    ("bad.csv", "a,0,0,0\nb,1,x,0\nc,0,1,0\n"),
    ("bad.yaml", "tag_bundles:\n  - name: b\n    layout:\n      - {id: 0, x: 0}\n"),
    ("bad.json", '{"points": [[0,0,0],[1,0,0],[1,0,0]]}'),
    ("bad.txt", "a,0,0,0\n"),
])
def test_bad_files_raise_the_cli_message(vantage, tmp_path, monkeypatch, name, text):
    monkeypatch.chdir(tmp_path)
    (tmp_path / name).write_text(text)
    with pytest.raises(ValueError) as error:
        vantage.load_layout(name)
    assert str(error.value) == cli_error("analyze", name)
    with pytest.raises(ValueError) as error:
        vantage.analyze(name)
    assert str(error.value).startswith(name + ": ")


def test_format_override_and_unknown_options(vantage, tmp_path):
    path = tmp_path / "markers.txt"
    path.write_text("a,0,0,0\nb,1,0,0\nc,0,1,0\n")
    assert len(vantage.load_layout(path, format="csv")) == 3
    with pytest.raises(ValueError, match="format: expected auto, json, csv, apriltag, atracsys or ndi"):
        vantage.load_layout(path, format="xml")
    with pytest.raises(TypeError):  # a real signature: Python itself refuses the keyword
        vantage.load_layout(path, colour="red")  # type: ignore[call-arg]


def test_save_refuses_to_overwrite_unless_told(vantage, tmp_path):
    layout = vantage.Layout(vectors=TRIAD)
    vantage.save_layout(layout, tmp_path / "t.json")
    with pytest.raises(ValueError, match="exists already"):
        vantage.save_layout(layout, tmp_path / "t.json")
    vantage.save_layout(vantage.Layout(vectors=2 * TRIAD), tmp_path / "t.json", overwrite=True)
    np.testing.assert_array_equal(vantage.load_layout(tmp_path / "t.json").entries, 2 * TRIAD)


@pytest.mark.parametrize("args", [
    ("chessboard", dict(rows=4, cols=5, square=0.03)),
    ("charuco", dict(rows=5, cols=7, square=0.04, marker=0.03)),
    ("aprilgrid", dict(rows=2, cols=3, square=0.088, spacing=0.3)),
])
def test_board_matches_the_cli(vantage, tmp_path, args):
    board_type, options = args
    flags = [f"--{k}={v}" for k, v in options.items()]
    cli_json("layout", "board", "--type", board_type, *flags, "--out", tmp_path / "b.json")
    board = vantage.board(board_type, **options)
    assert board.to_dict() == vantage.load_layout(tmp_path / "b.json").to_dict()


def test_board_rejects_what_the_cli_rejects(vantage):
    with pytest.raises(ValueError, match="marker: only for charuco"):
        vantage.board("chessboard", rows=4, cols=5, square=1, marker=0.5)
    with pytest.raises(ValueError, match="type: expected chessboard, charuco or aprilgrid"):
        vantage.board("checker", rows=4, cols=5, square=1)


def test_data_vectors_and_pbar_over_viewpoints(vantage):
    vectors, weights = vantage.data_vectors(vantage.Layout(points=[[0, 0, 0], [1, 0, 0],
                                                                   [0, 2, 0]],
                                                           weights=[1, 4, 9]))
    np.testing.assert_array_equal(vectors, [[1, 0, 0], [0, 2, 0], [-1, 2, 0]])
    np.testing.assert_allclose(weights, [2, 3, 6])
    # Z = I: p-bar at (1,1,1)/sqrt(3) is sqrt(2/3); looking down an axis it is 1.
    a = np.array([[1, 1, 1], [0, 0, 1]]) / np.array([[np.sqrt(3)], [1]])
    np.testing.assert_allclose(vantage.pbar_at_viewpoints(TRIAD, a), [np.sqrt(2 / 3), 1],
                               rtol=1e-15)
    with pytest.raises(ValueError, match="viewpoints"):
        vantage.pbar_at_viewpoints(TRIAD, [[0, 0, 2]])


def test_cli_reads_what_python_writes(vantage, tmp_path):
    layout = vantage.load_layout(LAYOUTS / "mocap_rigid_body.csv")
    vantage.save_layout(layout, tmp_path / "body.json")
    out, _ = run_cli("weights", tmp_path / "body.json", "--json")
    assert '"n": 5' in out


def test_save_layout_writes_the_format_the_extension_names(vantage, tmp_path):
    body = vantage.load_layout(LAYOUTS / "mocap_rigid_body.csv")
    assert body.names == ["hub", "arm_long", "arm_short", "arm_side", "mast"]
    vantage.save_layout(body, tmp_path / "body.csv")
    text = (tmp_path / "body.csv").read_text()
    assert text.splitlines()[-5].startswith("hub,")
    assert "{" not in text
    again = vantage.load_layout(tmp_path / "body.csv")
    assert again.names == body.names
    np.testing.assert_array_equal(again.entries, body.entries)
    np.testing.assert_array_equal(again.weights, body.weights)
    vantage.save_layout(body, tmp_path / "body.json")
    assert vantage.load_layout(tmp_path / "body.json").names == body.names
    for name, expected in [("tags.yaml", "cannot write an AprilTag bundle"),
                           ("body.txt", "name the file .json, .csv, .ini or .rom")]:
        with pytest.raises(ValueError, match=expected):
            vantage.save_layout(body, tmp_path / name)
        assert not (tmp_path / name).exists()
    with pytest.raises(ValueError, match="holds marker positions"):
        vantage.save_layout(vantage.Layout(vectors=TRIAD), tmp_path / "triad.csv")
    # An NDI .rom holds the positions as float32 (these are exact) and leaves the names out.
    vantage.save_layout(body, tmp_path / "body.rom")
    assert (tmp_path / "body.rom").stat().st_size == 752
    tool = vantage.load_layout(tmp_path / "body.rom")
    assert tool.names == ["A", "B", "C", "D", "E"]
    np.testing.assert_array_equal(tool.entries, body.entries.astype(np.float32))


def test_layout_names_are_given_checked_and_defaulted(vantage):
    named = vantage.Layout(points=[[0, 0, 0], [1, 0, 0], [0, 1, 0]], names=["a", "b", "c"])
    assert named.names == ["a", "b", "c"]
    assert named.to_dict()["names"] == ["a", "b", "c"]
    assert vantage.Layout(vectors=TRIAD).names == ["v0", "v1", "v2"]
    assert "names" not in vantage.Layout(vectors=TRIAD).to_dict()
    with pytest.raises(ValueError, match=r"names\[2\]: repeats names\[0\]"):
        vantage.Layout(points=[[0, 0, 0], [1, 0, 0], [0, 1, 0]], names=["a", "b", "a"])
    with pytest.raises(ValueError, match="names: expected 3 entries"):
        vantage.Layout(points=[[0, 0, 0], [1, 0, 0], [0, 1, 0]], names=["a"])
    with pytest.raises(ValueError, match="got a string"):
        vantage.Layout(vectors=TRIAD, names="xyz")
