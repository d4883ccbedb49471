"""vantage.place: the fields of ``vantage place --json`` (the same checks, placement and JSON
writer), the placed vantage.Layout, the exhaustive optimum against a brute force over every
K-subset with vantage.analyze (docs/math.md §21's objective: coverage first, then the certified
p-bar_min), and bad input naming the keyword."""

import inspect
import itertools
import json
import warnings

import pytest

from conftest import SOURCE, assert_same, cli_json

BODIES = SOURCE / "examples" / "bodies"
CUBE_SITES = BODIES / "cube_sites.json"
CAPSULE = BODIES / "capsule.obj"

# Two placements are not told apart closer than the certificate tolerance in t (1e-6 and
# finer); p-bar_min = sqrt(1 - t^2) near 0.9 moves by about half of that.
OBJECTIVE_TIE = 1e-6


def without_written(fields):
    fields = dict(fields)
    fields.pop("written")
    return fields


def test_sites_file_matches_the_cli_field_for_field(vantage, tmp_path):
    report = vantage.place(sites=str(CUBE_SITES), markers=4, out=tmp_path / "py.json")
    cli = cli_json("place", "--sites", CUBE_SITES, "--markers", 4, "--out", tmp_path / "cli.json")
    assert isinstance(report, vantage.PlaceReport)
    assert_same(without_written(report.to_dict()), without_written(cli))
    assert report.written == str(tmp_path / "py.json") and report.search == "exhaustive"
    assert report.drawn is None and report.subsets == cli["subsets"]
    written = json.loads((tmp_path / "py.json").read_text())
    assert written["points"] == json.loads((tmp_path / "cli.json").read_text())["points"]
    # The placed layout: the chosen sites, analysing to the reported numbers.
    assert isinstance(report.layout, vantage.Layout) and len(report.layout) == 4
    analysed = vantage.analyze(report.layout)
    assert analysed.visibility.pbar_min == report.pbar_min
    assert analysed.visibility.trackable_fraction == report.coverage


def test_mesh_matches_the_cli_and_writes_nothing_without_out(vantage, tmp_path):
    args = dict(markers=10, candidates=60, random_trials=50, seed=3)
    report = vantage.place(str(CAPSULE), **args)
    cli = cli_json("place", CAPSULE, "--markers", 10, "--candidates", 60, "--random-trials", 50,
                   "--seed", 3, "--out", tmp_path / "cli.json")
    assert_same(without_written(report.to_dict()), without_written(cli))
    assert report.written is None and cli["written"] == str(tmp_path / "cli.json")
    assert report.drawn == cli["drawn"] and len(report.steps) == len(cli["steps"])
    assert list(tmp_path.iterdir()) == [tmp_path / "cli.json"]


def small_sites(tmp_path):
    """Eight of the cube's sites, two on each of the +x and -x faces, one on each other face."""
    cube = json.loads(CUBE_SITES.read_text())
    keep = [0, 1, 3, 4, 6, 9, 12, 15]
    sites = {"name": "eight cube sites", "points": [cube["points"][i] for i in keep],
             "normals": [cube["normals"][i] for i in keep], "visibility": cube["visibility"]}
    path = tmp_path / "eight.json"
    path.write_text(json.dumps(sites))
    return path, sites


def test_exhaustive_optimum_is_the_brute_force_best(vantage, tmp_path):
    path, sites = small_sites(tmp_path)
    markers = 4
    report = vantage.place(sites=path, markers=markers)
    assert report.search == "exhaustive"
    best = None
    for subset in itertools.combinations(range(len(sites["points"])), markers):
        layout = vantage.Layout(points=[sites["points"][i] for i in subset],
                                normals=[sites["normals"][i] for i in subset],
                                visibility=sites["visibility"])
        try:
            v = vantage.analyze(layout, crosscheck=False).visibility
        except vantage.NumericalError as error:
            v = error.result.visibility
        value = (v.trackable_fraction, v.pbar_min if v.certificate.certified else 0.0)
        best = value if best is None or value > best else best
    assert report.coverage == best[0]
    assert report.pbar_min == pytest.approx(best[1], abs=OBJECTIVE_TIE)


def test_bad_input_raises_naming_the_keyword(vantage, tmp_path):
    out = tmp_path / "o.json"
    calls = [
        ("body", dict(body=str(CAPSULE), sites=str(CUBE_SITES), markers=4)),
        ("body", dict(markers=4)),
        ("markers", dict(sites=str(CUBE_SITES), markers=2)),
        ("markers", dict(sites=str(CUBE_SITES), markers=17)),
        ("min_separation", dict(sites=str(CUBE_SITES), markers=4, min_separation=-1.0)),
        ("candidates", dict(sites=str(CUBE_SITES), markers=4, candidates=10)),
        ("perturbations", dict(sites=str(CUBE_SITES), markers=4, perturbations=-1)),
        ("cone_deg", dict(sites=str(CUBE_SITES), markers=4, cone_deg=200.0)),
        ("workspace", dict(sites=str(CUBE_SITES), markers=4, workspace=(0.0, 0.0, 1.0))),
        ("out", dict(sites=str(CUBE_SITES), markers=4, out=tmp_path / "none" / "o.json")),
        # Issue 36, item 8: a directory given as a file named no argument.
        ("keep", dict(sites=str(CUBE_SITES), markers=4, keep=tmp_path)),
        ("sites", dict(sites=tmp_path, markers=4)),
    ]
    for field, kwargs in calls:
        with pytest.raises(ValueError) as error:
            vantage.place(out=kwargs.pop("out", out), **kwargs)
        assert error.value.field == field, (field, str(error.value))
    assert not out.exists() and not (tmp_path / "none").exists()


def test_everything_after_body_is_keyword_only(vantage):
    parameters = list(inspect.signature(vantage.place).parameters.values())
    assert parameters[0].name == "body"
    assert parameters[0].kind is inspect.Parameter.POSITIONAL_OR_KEYWORD
    assert all(p.kind is inspect.Parameter.KEYWORD_ONLY for p in parameters[1:])
    markers = next(p for p in parameters if p.name == "markers")
    assert markers.default is inspect.Parameter.empty


def test_tracker_objective_matches_the_cli_and_is_what_tre_reports(vantage, tmp_path):
    """Issue 35: objective='tracker' gives the CLI's JSON, and its value is vantage.tre's largest
    worst.rms_bound on the placed layout, to the bit."""
    targets = [[0.0, 0.0, -2.0], [1.0, 1.0, 0.0]]
    report = vantage.place(sites=CUBE_SITES, markers=6, objective="tracker", targets=targets,
                           fle_sigma=(0.1, 0.3))
    cli = cli_json("place", "--sites", CUBE_SITES, "--markers", 6, "--objective", "tracker",
                   "--target", "0,0,-2", "--target", "1,1,0", "--fle-sigma", "0.1,0.3",
                   "--out", tmp_path / "cli.json")
    assert_same(without_written(report.to_dict()), without_written(cli))
    assert report.objective["name"] == "tracker"
    tre = vantage.tre(report.layout, targets=targets, fle_sigma=(0.1, 0.3))
    assert report.objective["value"] == max(t.worst.rms_bound for t in tre.targets)
    # The layout keeps its sensor block, which vantage.analyze evaluates to the same value.
    sensor = vantage.analyze(report.layout, crosscheck=False).sensor
    assert sensor["type"] == "tracker"
    assert sensor["value"] == report.objective["value"]


def test_an_approach_matches_the_cli_and_is_the_largest_of_crb_at_each_distance(vantage, tmp_path):
    """Issue 35: distances= is --distances (the same JSON), and the value is the largest over the
    distances of vantage.crb's worst on the placed layout with the same camera."""
    camera = dict(focal=900.0, noise_px=0.3, crb_samples=300)
    report = vantage.place(sites=CUBE_SITES, markers=5, objective="camera",
                           distances=[6.0, 2.0, 12.0], **camera)
    cli = cli_json("place", "--sites", CUBE_SITES, "--markers", 5, "--objective", "camera",
                   "--distances", "6,2,12", "--focal", 900, "--noise-px", 0.3, "--crb-samples",
                   300, "--out", tmp_path / "cli.json")
    assert_same(without_written(report.to_dict()), without_written(cli))
    aim = report.objective["camera"]["aim"]
    worst = [vantage.crb(report.layout, distance=d, focal=900.0, noise_px=0.3, samples=300,
                         aim=aim).worst.rot_rms_deg for d in (6.0, 2.0, 12.0)]
    assert report.objective["value_deg"] == max(worst)
    assert [step["value_deg"] for step in report.objective["approach"]] == worst
    for bad in ([6.0, -1.0], [], [6.0, 6.0]):
        with pytest.raises(ValueError) as error:
            vantage.place(sites=CUBE_SITES, markers=5, objective="camera", distances=bad,
                          **camera)
        assert error.value.field == "distances", (bad, str(error.value))


def test_incomplete_placement_keeps_its_layout_and_allow_partial_returns_it(vantage, tmp_path):
    """Issue 35 item 5: the best incomplete answer is on the error, and allow_partial returns it
    (and writes it) with a warning."""
    out = tmp_path / "part.json"
    with pytest.raises(vantage.NumericalError) as error:
        vantage.place(sites=CUBE_SITES, markers=3, cone_deg=60.0, out=out)
    assert error.value.result.status == "incomplete"
    assert isinstance(error.value.result.layout, vantage.Layout)
    assert len(error.value.result.layout) == 3 and not out.exists()
    with pytest.warns(RuntimeWarning, match="allow_partial"):
        report = vantage.place(sites=CUBE_SITES, markers=3, cone_deg=60.0, out=out,
                               allow_partial=True)
    assert report.status == "incomplete" and report.written == str(out) and out.exists()


def test_objective_settings_name_their_keyword(vantage, tmp_path):
    calls = [
        ("objective", dict(objective="x")),
        ("focal", dict(objective="camera", distance=5.0, noise_px=1.0)),
        ("targets", dict(objective="tracker", fle_rms=0.2)),
        ("fle_rms", dict(objective="tracker", targets=[0.0, 0.0, 0.0])),
        ("fle_rms", dict(objective="tracker", targets=[0.0, 0.0, 0.0], fle_rms=0.2,
                         fle_sigma=(0.1, 0.1))),
        ("targets", dict(targets=[0.0, 0.0, 0.0], fle_rms=0.2)),
        ("aim", dict(objective="camera", distance=5.0, focal=800.0, noise_px=1.0,
                     aim=(0.0, float("nan"), 0.0))),
        ("min_coverage", dict(min_coverage=1.5)),
    ]
    for field, kwargs in calls:
        with pytest.raises(ValueError) as error:
            vantage.place(sites=CUBE_SITES, markers=4, **kwargs)
        assert error.value.field == field, (field, str(error.value))


def box_obj(path, lo, hi):
    """An axis-aligned box [lo, hi] as a closed OBJ mesh (outward winding)."""
    corners = [(x, y, z) for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])]
    faces = [(1, 2, 4, 3), (5, 7, 8, 6), (1, 5, 6, 2), (3, 4, 8, 7), (1, 3, 7, 5), (2, 6, 8, 4)]
    lines = ["v %r %r %r" % c for c in corners]
    lines += ["f %d %d %d\nf %d %d %d" % (a, b, c, a, c, d) for a, b, c, d in faces]
    path.write_text("\n".join(lines) + "\n")
    return path


def test_exclude_matches_the_cli_and_keeps_markers_out(vantage, tmp_path):
    """Issue 35 item 4: exclude= is --exclude (the same JSON), no marker is in the keep-out box
    (the capsule's top half, z > 0.2, widened past the body) and the dropped sites are counted."""
    keep_out = box_obj(tmp_path / "top.obj", (-1.0, -1.0, 0.2), (1.0, 1.0, 2.0))
    args = dict(markers=6, candidates=120, random_trials=30, seed=5, min_coverage=0.5,
                allow_partial=True)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        report = vantage.place(CAPSULE, exclude=[keep_out], **args)
    cli = cli_json("place", CAPSULE, "--exclude", keep_out, "--markers", 6, "--candidates", 120,
                   "--random-trials", 30, "--seed", 5, "--min-coverage", 0.5, "--allow-partial",
                   "--out", tmp_path / "cli.json")
    assert_same(without_written(report.to_dict()), without_written(cli))
    assert report.excluded > 0 and report.excluded == cli["excluded"]
    assert report.n_candidates + report.excluded == report.drawn
    assert all(point[2] <= 0.2 for point in report.layout.entries)
    # One path alone is the same as a list of one.
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        single = vantage.place(CAPSULE, exclude=keep_out, **args)
    assert single.chosen.tolist() == report.chosen.tolist()


def test_exclude_and_region_bad_input_names_the_keyword(vantage, tmp_path):
    out = tmp_path / "o.json"
    box = box_obj(tmp_path / "box.obj", (-1.0, -1.0, 0.5), (1.0, 1.0, 2.0))
    calls = [
        ("exclude", dict(sites=CUBE_SITES, exclude=box)),
        ("exclude", dict(body=CAPSULE, exclude=[box, 3])),
        ("exclude", dict(body=CAPSULE, exclude=tmp_path / "none.obj")),
        ("region", dict(body=CAPSULE, region=tmp_path / "none.obj")),
    ]
    for field, kwargs in calls:
        with pytest.raises(ValueError) as error:
            vantage.place(markers=4, out=out, **kwargs)
        assert error.value.field == field, (field, str(error.value))
    assert not out.exists()


def test_perturbations_match_the_cli(vantage, tmp_path):
    report = vantage.place(sites=CUBE_SITES, markers=6, exhaustive_limit=0, perturbations=5)
    cli = cli_json("place", "--sites", CUBE_SITES, "--markers", 6, "--exhaustive-limit", 0,
                   "--perturbations", 5, "--out", tmp_path / "cli.json")
    assert_same(without_written(report.to_dict()), without_written(cli))
    assert report.perturbations == 5 and report.improving_perturbations is not None
