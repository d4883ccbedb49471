"""vantage: evaluate and design fiducial layouts for pose from a single affine image.

Bindings over the C++ libraries: vantage.analyze calls the library's one layout report
(report::analyze_layout), vantage.pose its one pose front door (estimate_pose). Every function
returns a typed result (vantage.LayoutReport, vantage.PoseEstimate, ...) whose attributes are
the fields of the matching ``vantage`` subcommand's ``--json`` output, vectors and matrices as
numpy arrays; ``to_dict()`` is that JSON object.

Arrays are numpy, one point or vector per row: layouts and models are ``n x 3``, image points
``n x 2``. Any numeric dtype (float32, int) is converted to float64; a ``3 x n`` array is
rejected with a message telling you to pass its transpose.

The CLI's size limits hold here too (README "Limits"); ``allow_large=True`` lifts them as
``--allow-large`` does. The long computations release the GIL.

Errors: bad input raises ``ValueError`` with the CLI's message and the attributes ``field``,
``index``, ``problem`` and ``source`` (None when absent); a computation that finished but failed
numerically (the CLI's exit status 1) raises :class:`NumericalError` with ``status``,
``message`` and the full typed ``result``.
"""

from __future__ import annotations

import functools
import os
from typing import (Any, Callable, Iterable, Literal, Optional, Sequence, Tuple, TypeVar,
                    Union, overload)

import numpy.typing as npt

from . import _vantage
from ._results import (
    BoundCheck, Certificate, Crosscheck, DesignCoplanarity, DesignDirect, DesignResult, DesignState,
    DesignStep, DistanceDifference, DropoutEntry, EstimatorStats, ExactViewpoint, Identification,
    LayoutCoplanarity,
    LayoutReport, LayoutVisibility, LostRegion, Orientation, PaperLmi, PerTrial, PoseAlternative,
    PoseCamera, PoseEstimate, SimulationReport, SimulationVisibility, Solver, Statistic, Swap,
    VisibilityCertificate, VisibilityDropoutEntry, WeightsResult, WeightsSuggestion, Workspace,
)
from ._tool_results import (
    CrbBound, CrbReport, CrbSweepRow, DesignSensorResult, IdentPair, IdentReport, IdentTool,
    PlaceBaseline, PlaceReport,
    PlaceRobust, PlaceStep, TreAtDirection, TreExtreme, TreMonteCarlo, TreReport, TreTarget,
)
from ._vantage import (
    Layout,
    NumericalError,
    __version__,
    board,
    data_vectors,
    load_correspondences,
    pbar_at_viewpoints,
    pose_methods,
    save_layout,
)

__all__ = [
    "BoundCheck", "Certificate", "CrbBound", "CrbReport", "CrbSweepRow", "Crosscheck", "DesignCoplanarity", "DesignDirect",
    "DesignResult", "DesignSensorResult", "DesignState", "DesignStep", "DistanceDifference", "DropoutEntry", "EstimatorStats", "ExactViewpoint", "IdentPair", "IdentReport",
    "IdentTool", "Identification", "Layout",
    "LayoutCoplanarity", "LayoutReport", "LayoutVisibility", "LostRegion", "NumericalError", "Orientation", "PaperLmi", "PerTrial",
    "PlaceBaseline", "PlaceReport", "PlaceRobust", "PlaceStep", "PoseAlternative", "PoseCamera", "PoseEstimate", "SimulationReport", "SimulationVisibility",
    "Solver", "Statistic", "Swap", "TreAtDirection", "TreExtreme", "TreMonteCarlo", "TreReport",
    "TreTarget", "VisibilityCertificate", "VisibilityDropoutEntry",
    "WeightsResult", "WeightsSuggestion", "Workspace", "__version__", "analyze", "board", "crb",
    "data_vectors", "design", "ident", "load_correspondences", "load_layout", "orient",
    "pbar_at_viewpoints", "place", "pose", "pose_methods", "save_layout", "simulate", "tre", "weights",
]

#: A layout argument: a vantage.Layout or the path of a layout file (.json, .csv, .yaml/.yml).
LayoutArg = Union[Layout, str, "os.PathLike[str]", None]

_R = TypeVar("_R")


def _typed_errors(wrap: Callable[[Any], Any]) -> Callable[[Callable[..., _R]], Callable[..., _R]]:
    """Makes a NumericalError's ``result`` the typed result (``wrap`` of its dict)."""

    def decorate(function: Callable[..., _R]) -> Callable[..., _R]:
        @functools.wraps(function)
        def call(*args: Any, **kwargs: Any) -> _R:
            try:
                return function(*args, **kwargs)
            except NumericalError as error:
                if isinstance(error.result, dict):
                    error.result = wrap(error)
                raise

        return call

    return decorate


def load_layout(path: Union[str, "os.PathLike[str]"], *, format: Optional[str] = None,
                tag_points: Optional[str] = None, bundle: Optional[str] = None,
                allow_large: bool = False) -> Layout:
    """Reads a layout file: .json (vantage layout), .csv (name,x,y,z[,weight]) or .yaml/.yml
    (AprilTag tag_bundles). format 'auto' (by extension), 'json', 'csv' or 'apriltag';
    tag_points 'corners' or 'centres'; bundle: the AprilTag bundle's name (needed when the file
    has several); allow_large=True reads files up to 1 GiB instead of 64 MiB."""
    return _vantage.load_layout(path, format=format, tag_points=tag_points, bundle=bundle,
                                allow_large=allow_large)


@_typed_errors(lambda error: LayoutReport(error.result, error.text))
def analyze(layout: LayoutArg = None, *, vectors: Optional[npt.ArrayLike] = None,
            points: Optional[npt.ArrayLike] = None, weights: Optional[npt.ArrayLike] = None,
            swaps: int = 5, crosscheck: bool = True, pair_weighting: str = "geometric",
            dropout: bool = False, allow_large: bool = False, format: Optional[str] = None,
            tag_points: Optional[str] = None, bundle: Optional[str] = None) -> LayoutReport:
    """The report of a layout (as ``vantage analyze --json``): its certified worst viewpoint.

    layout: a vantage.Layout or a layout file, read with format ('auto', 'json', 'csv',
    'apriltag'), tag_points ('corners', 'centres') and bundle (the AprilTag bundle's name);
    or instead vectors= / points= (n x 3) with weights= (n, > 0).
    swaps: how many of the most harmful swaps of two data vectors to report (>= 1).
    crosscheck: run the independent cross-check of the worst viewpoint.
    pair_weighting: point mode's weight of the free vector z_j - z_i: 'geometric' or
    'arithmetic' mean of the markers' weights.
    dropout: also analyse the layout without each of its entries (``--dropout``).
    allow_large: lift the size limits (README "Limits"), as ``--allow-large``.

    Raises ValueError on bad input and NumericalError (its ``result`` the LayoutReport) when the
    report is not usable; its status says why: 'degenerate', 'near_degenerate', the solver's
    status when not certified, 'crosscheck_disagrees', 'dropout_not_certified',
    'exact_rays_disagree' (on a body, the exact rays at the worst viewpoint contradict the
    occlusion grid) or 'visibility_not_certified'.
    """
    fields, brief = _vantage.analyze(
        layout, vectors=vectors, points=points, weights=weights, swaps=swaps,
        crosscheck=crosscheck, pair_weighting=pair_weighting, dropout=dropout,
        allow_large=allow_large, format=format, tag_points=tag_points, bundle=bundle)
    return LayoutReport(fields, brief)


@_typed_errors(lambda error: CrbReport(error.result))
def crb(layout: LayoutArg = None, *, points: Optional[npt.ArrayLike] = None,
        distance: float, focal: float, noise_px: float,
        principal_point: Optional[npt.ArrayLike] = None,
        direction: Optional[npt.ArrayLike] = None,
        sweep_distance: Optional[Tuple[float, float, int]] = None, samples: int = 10000,
        threads: int = 0, allow_large: bool = False, format: Optional[str] = None,
        tag_points: Optional[str] = None, bundle: Optional[str] = None,
        aim: Optional[Sequence[float]] = None) -> CrbReport:
    """The Cramér–Rao bound of the pose from one pinhole image over every viewpoint (as
    ``vantage crb --json``; docs/math.md §22).

    layout: a vantage.Layout or a layout file (points), or points= (n x 3).
    distance: the camera's distance from the markers' centroid, or from aim (x, y, z) when
    given (layout units, above the layout's radius about it); focal: pixels; noise_px: pixel
    noise per coordinate.
    direction: also the bound at this viewing direction (body toward camera), with its 6 x 6
    covariance. sweep_distance: (D1, D2, N), the worst and median bound at N distances (N
    bounded, README "Limits"). samples: the map's lattice density (directions on the whole
    sphere; a workspace gets its share, at least 100). allow_large: lift the size limits, as
    ``--allow-large``.

    Raises ValueError on bad input and NumericalError (its ``result`` the CrbReport) when no
    sampled direction is trackable (status 'untrackable', 'ill_conditioned' or 'unbounded', as
    the CLI's exit status 1).
    """
    return CrbReport(_vantage.crb(
        layout, points=points, distance=distance, focal=focal, noise_px=noise_px,
        principal_point=principal_point, direction=direction, sweep_distance=sweep_distance,
        samples=samples, threads=threads, allow_large=allow_large, format=format,
        tag_points=tag_points, bundle=bundle, aim=aim))


@_typed_errors(lambda error: TreReport(error.result))
def tre(layout: LayoutArg = None, *, points: Optional[npt.ArrayLike] = None,
        targets: Optional[npt.ArrayLike] = None, fle_rms: Optional[float] = None,
        fle_sigma: Optional[Tuple[float, float]] = None,
        direction: Optional[npt.ArrayLike] = None, monte_carlo: int = 0, seed: int = 1,
        threads: int = 0, allow_large: bool = False, format: Optional[str] = None,
        tag_points: Optional[str] = None, bundle: Optional[str] = None) -> TreReport:
    """The target registration error of a tool on a 3-D optical tracker (as ``vantage tre
    --json``; docs/math.md §23): markers registered by least squares without scale, the error of
    each target to first order, in the layout's units.

    layout: a vantage.Layout or a layout file (points, tool frame), or points= (n x 3).
    targets: one target [x, y, z] or an n x 3 array (tool frame).
    fle_rms: isotropic FLE with E|e|^2 = fle_rms^2 (adds Fitzpatrick 1998's ``rms_isotropic``);
    or fle_sigma: (sigma_perp, sigma_axial), the standard deviations across and along the
    tracker's line of sight (NDI: (0.0995, 0.2985) mm). Exactly one of the two.
    direction: also the TRE and its 3 x 3 covariance at this line of sight (tool toward tracker,
    tool frame). monte_carlo: trials of the seeded Monte Carlo check (0 or >= 1000,
    bounded per target, README "Limits"), at direction or else at the worst line of sight; seed,
    threads: as ``--seed``, ``--threads``. allow_large: lift the size limits, as
    ``--allow-large``.

    Raises ValueError on bad input and NumericalError (status 'untracked', its ``result`` the
    TreReport) when a target is tracked from no direction, as the CLI's exit status 1.
    """
    return TreReport(_vantage.tre(
        layout, points=points, targets=targets, fle_rms=fle_rms, fle_sigma=fle_sigma,
        direction=direction, monte_carlo=monte_carlo, seed=seed, threads=threads,
        allow_large=allow_large, format=format, tag_points=tag_points, bundle=bundle))


def ident(tools: Iterable[Union[Layout, str, "os.PathLike[str]"]], *,
          min_visible: Optional[int] = None, same_tolerance: float = 0.01,
          format: Optional[str] = None, allow_large: bool = False) -> IdentReport:
    """How close the tools of a library come to each other by their inter-marker distances (as
    ``vantage ident --json``; docs/math.md §24, Eq. 24.4): for every two tools, and each tool
    against itself relabelled, the least over views of k markers of one and injective
    labellings by the other of the largest inter-marker distance error, the markers that give
    it, whether it fits as a rotation or only as a reflection, and each pair's verdict
    ('same_tool', 'mirror' or 'distinct': whether every marker matches within
    ``same_tolerance``, in the tools' units), with the n x n ``matrix``.

    tools: vantage.Layout objects (points), tool files (.json, .csv, Atracsys .ini, NDI .rom)
    or folders of them, read with format ('auto', 'json', 'csv', 'atracsys', 'ndi') and
    allow_large as ``--format``, ``--allow-large``; a Layout's ``file`` is None; the number of
    tools is bounded (README "Limits"; allow_large=True lifts it). min_visible: k >= 3 for every
    tool, at most every tool's markers; None: each tool's own (a .rom's minimum markers, a
    layout's visibility.min_visible, else 3), a pair the smaller of its two.

    Raises ValueError on bad input (its ``field`` 'min_visible', 'same_tolerance' or 'tools').
    """
    return IdentReport(_vantage.ident(tools, min_visible=min_visible,
                                      same_tolerance=same_tolerance, format=format,
                                      allow_large=allow_large))


def _place_report(fields: Any) -> PlaceReport:
    fields = dict(fields)
    layout = fields.pop("layout", None)
    return PlaceReport(fields, layout)


#: A file path argument.
PathArg = Union[str, "os.PathLike[str]"]


@_typed_errors(lambda error: _place_report(error.result))
def place(body: Optional[PathArg] = None, *, sites: Optional[PathArg] = None, markers: int,
          candidates: Optional[int] = None, cone_deg: Optional[float] = None,
          min_visible: Optional[int] = None,
          workspace: Optional[Tuple[float, float, float, float]] = None,
          min_separation: Optional[float] = None, keep: Optional[PathArg] = None,
          robust_dropout: bool = False, min_distance_difference: float = 0.0,
          seed: Optional[int] = None, threads: Optional[int] = None,
          random_trials: Optional[int] = None, exhaustive_limit: Optional[int] = None,
          out: Optional[PathArg] = None, overwrite: bool = False, objective: str = "affine",
          distance: Optional[float] = None, distances: Optional[Sequence[float]] = None,
          focal: Optional[float] = None, noise_px: Optional[float] = None,
          statistic: str = "worst",
          crb_samples: Optional[int] = None, aim: Optional[Sequence[float]] = None,
          targets: Optional[npt.ArrayLike] = None, fle_rms: Optional[float] = None,
          fle_sigma: Optional[Sequence[float]] = None, min_coverage: Optional[float] = None,
          allow_partial: bool = False, marker_diameter: float = 0.0,
          exclude: Union[None, PathArg, Sequence[PathArg]] = None,
          region: Optional[PathArg] = None, perturbations: int = 0) -> PlaceReport:
    """Choose ``markers`` (K) marker sites on a body so that every workspace direction is
    trackable and the certified worst case under visibility is best (as ``vantage place
    --json``; docs/math.md §21); the result's ``layout`` is the placed vantage.Layout.

    body: a mesh (STL, OBJ, PLY, glTF, ...) to sample ``candidates`` sites on (default 500),
    or sites: a point layout file with normals (its cones, min_visible, body and workspace
    apply); exactly one. cone_deg, min_visible, workspace (ax, ay, az, deg): as ``--cone-deg``,
    ``--min-visible``, ``--workspace``. marker_diameter: spheres whose centres sit half of it
    off the surface along the site normals (default 0: point markers). min_separation (default
    0; at least marker_diameter), keep (a layout file of the
    markers already on the body), robust_dropout, min_distance_difference, seed (1), threads (0:
    all cores), random_trials (1000), exhaustive_limit (5000): as the CLI's flags. out: write
    the placed layout (.json) there, all or nothing, only when the placement is complete;
    overwrite: replace an existing file. None: the CLI's default.

    objective: 'affine' (the paper's scale-free bound), 'camera' (the pinhole pose CRB: needs
    distance (or distances: an approach, the largest over them of the statistic), focal and
    noise_px; statistic 'worst', 'p95' or 'median'; crb_samples; aim (x, y, z), default the
    centre of the sites' bounding box) or 'tracker' (the worst RMS TRE:
    needs targets, one [x, y, z] or an n x 3 array, and fle_rms or fle_sigma (sigma_perp,
    sigma_axial)); the report's ``objective`` holds its value as ``vantage crb`` or ``vantage
    tre`` reports it on the placed layout (docs/math.md §21, "Objectives"). min_coverage: the
    least trackable fraction of the workspace's lattice, in (0, 1] (default: every direction
    but one); allow_partial: return (and write) the best answer even when it covers less, with
    a RuntimeWarning, instead of raising.

    exclude: one mesh or a sequence of meshes, keep-out volumes (propellers, a battery): sampled
    sites inside one or within marker_diameter of it are dropped (the report's ``excluded``
    counts them). region: a mesh on the body's surface, the only part sampled (normals oriented
    by the whole body). Both only with a body mesh (docs/math.md §21, "Where markers may go").
    perturbations: rounds of iterated local search after the swaps (``--perturbations``,
    default 0).

    Raises ValueError on bad input (its ``field`` the keyword, e.g. 'markers', 'body') and
    NumericalError (its ``result`` the PlaceReport, with the best ``layout`` found) when the
    placement leaves a workspace direction untracked or its analysis is not certified.
    """
    return _place_report(_vantage.place(
        body, sites=sites, markers=markers, candidates=candidates, cone_deg=cone_deg,
        min_visible=min_visible, workspace=workspace, min_separation=min_separation, keep=keep,
        robust_dropout=robust_dropout, min_distance_difference=min_distance_difference,
        seed=seed, threads=threads, random_trials=random_trials,
        exhaustive_limit=exhaustive_limit, out=out, overwrite=overwrite, objective=objective,
        distance=distance, distances=None if distances is None else list(distances), focal=focal, noise_px=noise_px, statistic=statistic,
        crb_samples=crb_samples, aim=aim, targets=targets, fle_rms=fle_rms, fle_sigma=fle_sigma,
        min_coverage=min_coverage, allow_partial=allow_partial, marker_diameter=marker_diameter,
        exclude=exclude, region=region, perturbations=perturbations))


def _design_result(fields: Any) -> Union[DesignResult, DesignSensorResult]:
    fields = dict(fields)
    augmented = fields.pop("augmented", None)
    if fields.get("objective") in ("camera", "tracker"):
        return DesignSensorResult(fields, augmented)
    return DesignResult(fields, augmented)


@overload
def design(layout: LayoutArg = None, *, vectors: Optional[npt.ArrayLike] = None,
           points: Optional[npt.ArrayLike] = None, weights: Optional[npt.ArrayLike] = None,
           candidates: Optional[npt.ArrayLike] = None, add: int = 1,
           candidates_only: bool = False, margin: float = 0.25, direct: bool = True,
           min_distance_difference: float = 0.0, allow_large: bool = False,
           format: Optional[str] = None,
           tag_points: Optional[str] = None, bundle: Optional[str] = None,
           objective: Literal["affine"] = "affine", distance: Optional[float] = None,
           distances: Optional[Sequence[float]] = None, focal: Optional[float] = None,
           noise_px: Optional[float] = None, statistic: str = "worst",
           crb_samples: Optional[int] = None, aim: Optional[Sequence[float]] = None,
           targets: Optional[npt.ArrayLike] = None, fle_rms: Optional[float] = None,
           fle_sigma: Optional[Sequence[float]] = None) -> DesignResult: ...


@overload
def design(layout: LayoutArg = None, *, vectors: Optional[npt.ArrayLike] = None,
           points: Optional[npt.ArrayLike] = None, weights: Optional[npt.ArrayLike] = None,
           candidates: Optional[npt.ArrayLike] = None, add: int = 1,
           candidates_only: bool = False, margin: float = 0.25, direct: bool = True,
           min_distance_difference: float = 0.0, allow_large: bool = False,
           format: Optional[str] = None,
           tag_points: Optional[str] = None, bundle: Optional[str] = None,
           objective: Literal["camera", "tracker"], distance: Optional[float] = None,
           distances: Optional[Sequence[float]] = None, focal: Optional[float] = None,
           noise_px: Optional[float] = None, statistic: str = "worst",
           crb_samples: Optional[int] = None, aim: Optional[Sequence[float]] = None,
           targets: Optional[npt.ArrayLike] = None, fle_rms: Optional[float] = None,
           fle_sigma: Optional[Sequence[float]] = None) -> DesignSensorResult: ...


@_typed_errors(lambda error: _design_result(error.result))
def design(layout: LayoutArg = None, *, vectors: Optional[npt.ArrayLike] = None,
           points: Optional[npt.ArrayLike] = None, weights: Optional[npt.ArrayLike] = None,
           candidates: Optional[npt.ArrayLike] = None, add: int = 1,
           candidates_only: bool = False, margin: float = 0.25, direct: bool = True,
           min_distance_difference: float = 0.0, allow_large: bool = False,
           format: Optional[str] = None,
           tag_points: Optional[str] = None, bundle: Optional[str] = None,
           objective: str = "affine", distance: Optional[float] = None,
           distances: Optional[Sequence[float]] = None, focal: Optional[float] = None,
           noise_px: Optional[float] = None, statistic: str = "worst",
           crb_samples: Optional[int] = None, aim: Optional[Sequence[float]] = None,
           targets: Optional[npt.ArrayLike] = None, fle_rms: Optional[float] = None,
           fle_sigma: Optional[Sequence[float]] = None) -> Union[DesignResult, DesignSensorResult]:
    """Add ``add`` markers or directions where the worst viewpoint is weakest (as ``vantage
    design --json``); the result's ``augmented`` is the new vantage.Layout.

    layout, vectors, points, weights, format, tag_points, bundle: as vantage.analyze;
    candidates (k x 3): where additions may go. candidates_only: only from the candidates.
    margin: the free search's box around the layout (relative to its size). direct: also run
    the direct optimiser. min_distance_difference: point layouts, every addition keeps the
    least difference of two inter-marker distances at or above this (ART's identification rule,
    docs/math.md §24; ``--min-distance-difference``; 0: none); the layout must keep it itself.
    allow_large: lift the time budget (README "Limits").

    objective 'camera' or 'tracker' (``--objective``; docs/math.md §21, "In design"): the
    ``add`` of the layout's candidates that make the camera's pose CRB or the tracker's TRE
    best, chosen by vantage.place's search with the layout's markers kept, the layout seen whole
    (one with normals, cones or a body is refused); the settings as vantage.place's (distance
    or distances, focal, noise_px, statistic, crb_samples, aim; targets, fle_rms or fle_sigma).
    Returns a DesignSensorResult; margin and direct are the augmenter's and may not be changed.
    Raises NumericalError (its ``result`` the DesignSensorResult, with the best ``augmented``)
    when the answer leaves a direction untracked.
    """
    result = _vantage.design(
        layout, vectors=vectors, points=points, weights=weights, candidates=candidates, add=add,
        candidates_only=candidates_only, margin=margin, direct=direct,
        min_distance_difference=min_distance_difference, allow_large=allow_large, format=format,
        tag_points=tag_points, bundle=bundle, objective=objective, distance=distance,
        distances=None if distances is None else list(distances), focal=focal,
        noise_px=noise_px, statistic=statistic, crb_samples=crb_samples, aim=aim,
        targets=targets, fle_rms=fle_rms, fle_sigma=fle_sigma)
    return _design_result(result)


@_typed_errors(lambda error: WeightsResult(error.result))
def weights(layout: LayoutArg = None, *, vectors: Optional[npt.ArrayLike] = None,
            points: Optional[npt.ArrayLike] = None, allow_large: bool = False,
            format: Optional[str] = None, tag_points: Optional[str] = None,
            bundle: Optional[str] = None) -> WeightsResult:
    """Non-negative weights with sum_i w_i z_i = 0 (Prop. 3, Eq. 11), as ``vantage weights
    --json``; arguments as vantage.analyze."""
    return WeightsResult(_vantage.weights(
        layout, vectors=vectors, points=points, allow_large=allow_large, format=format,
        tag_points=tag_points, bundle=bundle))


@_typed_errors(lambda error: PoseEstimate(error.result))
def pose(model: Optional[npt.ArrayLike] = None, image: Optional[npt.ArrayLike] = None, *,
         method: str = "affine", measured: Optional[npt.ArrayLike] = None,
         image1: Optional[npt.ArrayLike] = None, image2: Optional[npt.ArrayLike] = None,
         weights: Optional[npt.ArrayLike] = None, focal: Optional[float] = None,
         principal_point: Optional[npt.ArrayLike] = None,
         free_vectors: Optional[str] = None) -> PoseEstimate:
    """One pose estimator (as ``vantage pose --method M --json``), through the library's one
    front door (estimate_pose).

    model n x 3 with image n x 2 in pixels (affine, affine-refined, perspective, standard,
    oi-foam, oi-svd) or measured n x 3 (full3d); image1 and image2 n x 2 (two-view); weights
    (n). focal (pixels, > 0) and principal_point [cx, cy] (pixels) as --focal and
    --principal-point; free_vectors 'auto' (default), 'all' or 'spanning'. vantage.pose_methods()
    lists the methods. Raises NumericalError when the estimate is degenerate or did not converge.
    """
    return PoseEstimate(_vantage.pose(
        model, image, method=method, measured=measured, image1=image1, image2=image2,
        weights=weights, focal=focal, principal_point=principal_point,
        free_vectors=free_vectors))


@_typed_errors(lambda error: Orientation(error.result))
def orient(model: npt.ArrayLike, measured: npt.ArrayLike, *,
           weights: Optional[npt.ArrayLike] = None, method: str = "qmethod") -> Orientation:
    """Rotation, translation and scale from 3-D correspondences, alpha * measured = R * model + p
    (as ``vantage orient --json``); method 'qmethod', 'svd' or 'foam'."""
    return Orientation(_vantage.orient(model, measured, weights=weights, method=method))


@_typed_errors(lambda error: SimulationReport(error.result))
def simulate(layout: LayoutArg = None, *, vectors: Optional[npt.ArrayLike] = None,
             points: Optional[npt.ArrayLike] = None, trials: int = 1000,
             camera: str = "affine", noise_px: float = 0.0, snr_db: Optional[float] = None,
             noise: str = "gaussian", range: float = 10.0, focal_px: float = 1000.0,
             principal_point: Sequence[float] = (0.0, 0.0),
             lateral_offset: Sequence[float] = (0.0, 0.0), viewpoint: str = "random",
             methods: Sequence[str] = (), seed: int = 1, threads: int = 0,
             per_trial: bool = False, allow_large: bool = False, format: Optional[str] = None,
             tag_points: Optional[str] = None, bundle: Optional[str] = None) -> SimulationReport:
    """Monte Carlo of every applicable estimator on seeded views of the layout, with the bound
    check of Eq. (26) / Eq. (30) on the affine camera (as ``vantage simulate --json``).

    camera 'affine' or 'pinhole'; noise_px (pixels) or snr_db; noise 'gaussian' or 'uniform'...
    as the CLI's options of the same names; methods: the estimators (empty: every applicable
    one); threads 0: all cores; per_trial: keep every trial's values. allow_large lifts the
    limits on trials (README "Limits"). Raises NumericalError when the bound check fails.
    """
    return SimulationReport(_vantage.simulate(
        layout, vectors=vectors, points=points, trials=trials, camera=camera, noise_px=noise_px,
        snr_db=snr_db, noise=noise, range=range, focal_px=focal_px,
        principal_point=list(principal_point), lateral_offset=list(lateral_offset),
        viewpoint=viewpoint, methods=list(methods), seed=seed, threads=threads,
        per_trial=per_trial, allow_large=allow_large, format=format, tag_points=tag_points,
        bundle=bundle))
