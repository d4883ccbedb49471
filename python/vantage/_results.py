"""Typed results: each class is a view of the one JSON object the matching ``vantage``
subcommand prints with ``--json`` (written by the C++ library's own JSON writer; nothing is
recomputed here). Attributes are typed, vectors and matrices are numpy arrays (one point or
vector per row), a number the JSON writes as null (not finite) is ``nan``, and ``to_dict()``
returns that JSON object as plain Python (``json.loads`` of the CLI's output).
"""

from __future__ import annotations

import copy
import math
from typing import Any, Dict, List, Mapping, Optional, Tuple

import numpy as np
import numpy.typing as npt

from ._vantage import Layout

__all__ = [
    "BoundCheck", "Certificate", "Crosscheck", "DesignCoplanarity", "DesignDirect", "DesignResult",
    "DesignState", "DesignStep", "DropoutEntry", "EstimatorStats", "ExactViewpoint",
    "LayoutCoplanarity",
    "LayoutReport", "LayoutVisibility", "LostRegion", "Orientation", "PaperLmi", "PoseAlternative",
    "PerTrial", "PoseCamera", "PoseEstimate", "SimulationReport", "SimulationVisibility", "Solver",
    "Statistic", "Swap", "VisibilityCertificate", "VisibilityDropoutEntry", "WeightsResult",
    "WeightsSuggestion", "Workspace",
]

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]
Json = Dict[str, Any]


def _float(value: Any) -> float:
    """A JSON number; null (the writers' non-finite) is nan."""
    return math.nan if value is None else float(value)


def _floats(value: Any) -> FloatArray:
    """A JSON list (or list of lists) of numbers as a float64 array; null entries are nan."""
    return np.asarray([] if value is None else value, dtype=np.float64)


def _ints(value: Any) -> IntArray:
    return np.asarray(value, dtype=np.int64)


def _rows(value: Any) -> FloatArray:
    """A list of 3-vectors as a k x 3 array (0 x 3 when empty)."""
    return _floats(value).reshape(-1, 3)


def _text(value: Any) -> Optional[str]:
    return None if value is None else str(value)


class _JsonView:
    """The base of the typed results: keeps the JSON object it was made from."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        self._fields: Json = dict(fields)

    def to_dict(self) -> Json:
        """The JSON object of the CLI's ``--json`` output, as plain Python (a deep copy)."""
        return copy.deepcopy(self._fields)

    def __eq__(self, other: object) -> bool:
        return type(other) is type(self) and self._fields == other._fields  # type: ignore[attr-defined]

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        shown = ", ".join(f"{key}={_short(value)}" for key, value in self._fields.items()
                          if not isinstance(value, (dict, list)))
        return f"{type(self).__name__}({shown})"


def _short(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 40 else text[:37] + "..."


# ----------------------------------------------------------------------------- the layout report


class Certificate(_JsonView):
    """The global certificate of the worst viewpoint: t in [t_lower, t_upper] (Theorem 6)."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.t_upper: float = _float(fields["t_upper"])
        self.t_lower: float = _float(fields["t_lower"])
        self.certified: bool = bool(fields["certified"])


class PaperLmi(_JsonView):
    """The paper's single LMI (Eq. 33): its viewpoint, t, p-bar there and the SDP status."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.viewpoint: FloatArray = _floats(fields["viewpoint"])
        self.t: float = _float(fields["t"])
        self.pbar: float = _float(fields["pbar"])
        self.status: str = str(fields["status"])


class Crosscheck(_JsonView):
    """The independent cross-check of the worst viewpoint (method 'skipped' when not run)."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.method: str = str(fields["method"])
        self.ran: bool = self.method != "skipped"
        self.skipped: Optional[str] = _text(fields.get("skipped"))
        self.t: float = _float(fields.get("t"))
        self.agrees: Optional[bool] = fields.get("agrees")
        self.samples: int = int(fields.get("samples", 0))
        self.sample_spacing_rad: float = _float(fields.get("sample_spacing_rad"))
        self.samples_cover_cells: Optional[bool] = fields.get("samples_cover_cells")


class Swap(_JsonView):
    """The error when data vectors i and j are swapped (point mode: their marker pairs)."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.i: int = int(fields["i"])
        self.j: int = int(fields["j"])
        self.error_deg: float = _float(fields["error_deg"])
        self.ambiguous: bool = bool(fields["ambiguous"])
        self.pair_i: Optional[IntArray] = _ints(fields["pair_i"]) if "pair_i" in fields else None
        self.pair_j: Optional[IntArray] = _ints(fields["pair_j"]) if "pair_j" in fields else None


class Solver(_JsonView):
    """The global search: backend, status, cells solved, patches, the confirming SDP's status."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.backend: str = str(fields["backend"])
        self.status: str = str(fields["status"])
        self.cells_solved: int = int(fields["cells_solved"])
        self.patches: int = int(fields["patches"])
        self.sdp_status: str = str(fields["sdp_status"])


class LayoutCoplanarity(_JsonView):
    """How far the data vectors are from a plane: their smallest singular value and normal."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.smallest_singular_value: float = _float(fields["smallest_singular_value"])
        self.normal: FloatArray = _floats(fields["normal"])
        self.nearly_coplanar: bool = bool(fields["nearly_coplanar"])
        self.threshold: float = _float(fields["threshold"])


class DropoutEntry(_JsonView):
    """The layout without entry `index` (a marker or a vector): its worst viewpoint."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.index: int = int(fields["index"])
        self.pbar_min: float = _float(fields["pbar_min"])
        self.max_worst_case_error_deg: float = _float(fields["max_worst_case_error_deg"])
        self.worst_viewpoint: FloatArray = _floats(fields["worst_viewpoint"])
        self.n_vectors: int = int(fields["n_vectors"])
        self.certified: bool = bool(fields["certified"])


def _pair(value: Any) -> Optional[Tuple[int, int]]:
    return None if value is None else (int(value[0]), int(value[1]))


class DistanceDifference(_JsonView):
    """The least difference of two inter-marker distances (docs/math.md §24, Eq. 24.1), with
    marker ``lost`` removed when it is a dropout entry (None for the whole layout)."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.lost: Optional[int] = int(fields["lost"]) if "lost" in fields else None
        self.min_distance_difference: float = _float(fields["min_distance_difference"])
        self.pair_a: Optional[Tuple[int, int]] = _pair(fields["pair_a"])
        self.pair_b: Optional[Tuple[int, int]] = _pair(fields["pair_b"])


class Identification(DistanceDifference):
    """How a tracker tells the markers apart by their distances, and how far the layout is from
    its mirror image (docs/math.md §24; point layouts). ``min_distance_difference`` is ART's
    margin (nan with one pair), ``mirror_rms`` NDI's (0 for a layout equal to its mirror; an
    upper bound when ``mirror_certified`` is False, with ``mirror_rms_lower`` below it)."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.min_marker_separation: float = _float(fields["min_marker_separation"])
        self.separation_pair: Optional[Tuple[int, int]] = _pair(fields["separation_pair"])
        self.mirror_rms: float = _float(fields["mirror_rms"])
        self.mirror_rms_lower: float = _float(fields["mirror_rms_lower"])
        self.mirror_certified: bool = bool(fields["mirror_certified"])
        self.own_mirror: bool = bool(fields["own_mirror"])
        self.mirror_assignment: IntArray = _ints(fields["mirror_assignment"])
        self.under_dropout: List[DistanceDifference] = [
            DistanceDifference(e) for e in fields["under_dropout"]]
        self.worst_under_dropout: DistanceDifference = DistanceDifference(
            fields["worst_under_dropout"])


class Workspace(_JsonView):
    """The directions analysed: the cap {a : a . axis >= cos(half_angle_deg)}."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.axis: FloatArray = _floats(fields["axis"])
        self.half_angle_deg: float = _float(fields["half_angle_deg"])


def _workspace(value: Any) -> Optional[Workspace]:
    return None if value is None else Workspace(value)


class VisibilityCertificate(_JsonView):
    """t_lower (attained) <= the supremum of t over the trackable directions <= t_upper.
    ``certified``: proven without a body (cones are exact); ``certified_at_resolution``: proven
    on the body's occlusion grid, not under exact rays (docs/math.md §20)."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.t_upper: float = _float(fields["t_upper"])
        self.t_lower: float = _float(fields["t_lower"])
        self.certified: bool = bool(fields["certified"])
        self.certified_at_resolution: bool = bool(fields["certified_at_resolution"])


class ExactViewpoint(_JsonView):
    """With a body: what the reported worst viewpoint sees under exact rays (``agrees``: the
    same markers as the occlusion grid says)."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.visible_markers: IntArray = _ints(fields["visible_markers"])
        self.trackable: bool = bool(fields["trackable"])
        self.t: float = _float(fields["t"])
        self.agrees: bool = bool(fields["agrees"])


class LostRegion(_JsonView):
    """The untrackable part of the workspace and its largest connected region."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.fraction: float = _float(fields["fraction"])
        center = fields["largest_region_center"]
        self.largest_region_center: Optional[FloatArray] = (
            None if center is None else _floats(center))
        self.largest_region_radius_deg: float = _float(fields["largest_region_radius_deg"])


class VisibilityDropoutEntry(_JsonView):
    """The layout on its body without marker `lost`."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.lost: int = int(fields["lost"])
        self.status: str = str(fields["status"])
        self.t: float = _float(fields["t"])
        self.pbar_min: float = _float(fields["pbar_min"])
        self.max_worst_case_error_deg: float = _float(fields["max_worst_case_error_deg"])
        self.trackable_fraction: float = _float(fields["trackable_fraction"])


class LayoutVisibility(_JsonView):
    """The layout on its body (``vantage analyze --json`` "visibility"; docs/math.md §20): the
    worst viewpoint over the trackable directions of the workspace and its certificate.
    Viewpoints are signed (body -> camera); without a trackable direction they are None."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.model: str = str(fields["model"])
        self.min_visible: int = int(fields["min_visible"])
        self.workspace: Optional[Workspace] = _workspace(fields["workspace"])
        self.trackable_fraction: float = _float(fields["trackable_fraction"])
        self.status: str = str(fields["status"])
        self.t: float = _float(fields["t"])
        self.pbar_min: float = _float(fields["pbar_min"])
        self.max_worst_case_error_deg: float = _float(fields["max_worst_case_error_deg"])
        viewpoint = fields["worst_viewpoint"]
        self.worst_viewpoint: Optional[FloatArray] = (
            None if viewpoint is None else _floats(viewpoint))
        self.worst_viewpoints: FloatArray = _rows(fields["worst_viewpoints"])
        self.visible_markers: IntArray = _ints(fields["visible_markers"])
        self.certificate = VisibilityCertificate(fields["certificate"])
        self.occlusion_resolution_deg: Optional[float] = (
            None if fields["occlusion_resolution_deg"] is None
            else _float(fields["occlusion_resolution_deg"]))
        self.exact_viewpoint: Optional[ExactViewpoint] = (
            ExactViewpoint(fields["exact_viewpoint"]) if "exact_viewpoint" in fields else None)
        self.lost = LostRegion(fields["lost"])
        self.distance_to_body: Optional[FloatArray] = (
            _floats(fields["distance_to_body"]) if "distance_to_body" in fields else None)
        self.off_body: Optional[IntArray] = (
            _ints(fields["off_body"]) if "off_body" in fields else None)
        #: With a body: the markers whose cones face the workspace but which the body hides
        #: from every direction of the coverage lattice there (docs/math.md §20).
        self.hidden_by_body: Optional[IntArray] = (
            _ints(fields["hidden_by_body"]) if "hidden_by_body" in fields else None)
        self.dropout: Optional[List[VisibilityDropoutEntry]] = (
            [VisibilityDropoutEntry(e) for e in fields["dropout"]] if "dropout" in fields
            else None)
        self.dropout_by_harm: Optional[IntArray] = (
            _ints(fields["dropout_by_harm"]) if "dropout_by_harm" in fields else None)


class LayoutReport(_JsonView):
    """The report of one layout (``vantage analyze --json``; C++ report::LayoutReport).

    ``repr()`` is the library's brief report; ``usable`` says whether the numbers can be relied
    on and ``message`` (None when usable) says why not.
    """

    def __init__(self, fields: Mapping[str, Any], brief: str = "") -> None:
        super().__init__(fields)
        self._brief = brief
        self.name: str = str(fields["name"])
        self.mode: str = str(fields["mode"])
        self.n_vectors: int = int(fields["n_vectors"])
        self.worst_viewpoint: FloatArray = _floats(fields["worst_viewpoint"])
        self.worst_viewpoints: FloatArray = _rows(fields["worst_viewpoints"])
        self.t: float = _float(fields["t"])
        self.pbar_min: float = _float(fields["pbar_min"])
        self.ceiling: float = _float(fields["ceiling"])
        self.degenerate: bool = bool(fields["degenerate"])
        self.near_degenerate: bool = bool(fields["near_degenerate"])
        self.worst_case_errors_deg: FloatArray = _floats(fields["worst_case_errors_deg"])
        self.max_worst_case_error_deg: float = _float(fields["max_worst_case_error_deg"])
        self.certificate = Certificate(fields["certificate"])
        self.paper_lmi = PaperLmi(fields["paper_lmi"])
        self.crosscheck = Crosscheck(fields["crosscheck"])
        self.swaps: List[Swap] = [Swap(s) for s in fields["swaps"]]
        self.solver = Solver(fields["solver"])
        self.coplanarity = LayoutCoplanarity(fields["coplanarity"])
        self.identification: Optional[Identification] = (
            Identification(fields["identification"]) if "identification" in fields else None)
        self.dropout: Optional[List[DropoutEntry]] = (
            [DropoutEntry(e) for e in fields["dropout"]] if "dropout" in fields else None)
        self.visibility: Optional[LayoutVisibility] = (
            LayoutVisibility(fields["visibility"]) if "visibility" in fields else None)
        # The layout's sensor evaluated (``vantage analyze --json``'s "sensor"), as a dict.
        self.sensor: Optional[Json] = (
            copy.deepcopy(fields["sensor"]) if "sensor" in fields else None)
        self.usable: bool = bool(fields["usable"])
        self.message: Optional[str] = _text(fields.get("message"))

    def brief_report(self) -> str:
        """The verdict in a few lines (the head of ``vantage analyze``'s text report)."""
        return self._brief

    def __repr__(self) -> str:
        return self._brief.rstrip("\n") or super().__repr__()


# ----------------------------------------------------------------------------------------- pose


class PoseCamera(_JsonView):
    """The camera the estimate used: focal length (pixels; nan when none) and principal point."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.focal: float = _float(fields["focal"])
        self.principal_point: FloatArray = _floats(fields["principal_point"])


class PoseAlternative(_JsonView):
    """The other pose of an ambiguous estimate (the mirror solution), when evaluated."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.R: FloatArray = _floats(fields["R"])
        self.p: FloatArray = _floats(fields["p"])
        self.reprojection_rms_px: float = _float(fields["reprojection_rms_px"])


_POSE_COMMON = ("method", "n", "R", "p", "alpha", "status", "ambiguous", "reprojection_rms_px",
                "objective", "iterations", "camera", "message", "alternative")


class PoseEstimate(_JsonView):
    """One estimate of vantage.pose (``vantage pose --json``; C++ PoseEstimate).

    R (3 x 3) and p (3; its z is nan when the depth is unknown) take object to camera
    coordinates; ``diagnostics`` holds the method's own fields (README, "vantage pose"), lists
    of numbers as arrays.
    """

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.method: str = str(fields["method"])
        self.n: int = int(fields["n"])
        self.R: FloatArray = _floats(fields["R"])
        self.p: FloatArray = _floats(fields["p"])
        self.alpha: float = _float(fields["alpha"])
        self.status: str = str(fields["status"])
        self.ambiguous: bool = bool(fields["ambiguous"])
        self.reprojection_rms_px: float = _float(fields["reprojection_rms_px"])
        self.objective: float = _float(fields["objective"])
        self.iterations: int = int(fields["iterations"])
        self.camera = PoseCamera(fields["camera"])
        self.message: Optional[str] = _text(fields.get("message"))
        self.alternative: Optional[PoseAlternative] = (
            PoseAlternative(fields["alternative"]) if "alternative" in fields else None)
        self.diagnostics: Dict[str, Any] = {
            key: _floats(value) if isinstance(value, list) else value
            for key, value in fields.items() if key not in _POSE_COMMON}


class Orientation(_JsonView):
    """alpha * measured = R * model + p from 3-D correspondences (``vantage orient --json``)."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.method: str = str(fields["method"])
        self.n: int = int(fields["n"])
        self.R: FloatArray = _floats(fields["R"])
        self.p: FloatArray = _floats(fields["p"])
        self.alpha: float = _float(fields["alpha"])
        self.residual: float = _float(fields["residual"])
        self.eigen_gap: float = _float(fields["eigen_gap"])
        self.status: str = str(fields["status"])
        self.message: Optional[str] = _text(fields.get("message"))


# --------------------------------------------------------------------------- design and weights


class DesignState(_JsonView):
    """The layout's worst viewpoint before the additions."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.pbar_min: float = _float(fields["pbar_min"])
        self.worst_viewpoints: FloatArray = _rows(fields["worst_viewpoints"])
        self.max_worst_case_error_deg: float = _float(fields["max_worst_case_error_deg"])
        self.ceiling: float = _float(fields["ceiling"])
        self.n_vectors: int = int(fields["n_vectors"])
        self.t: float = _float(fields["t"])
        self.certified: bool = bool(fields["certified"])


class DesignStep(_JsonView):
    """One greedy addition: what was added and the worst viewpoint after it."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.added: FloatArray = _floats(fields["added"])
        self.name: Optional[str] = _text(fields.get("name"))
        self.pbar_min: float = _float(fields["pbar_min"])
        self.worst_viewpoints: FloatArray = _rows(fields["worst_viewpoints"])
        self.max_worst_case_error_deg: float = _float(fields["max_worst_case_error_deg"])
        self.ceiling: float = _float(fields["ceiling"])
        self.n_vectors: int = int(fields["n_vectors"])
        self.improved: bool = bool(fields["improved"])
        self.note: Optional[str] = _text(fields.get("note"))
        self.t: float = _float(fields["t"])
        self.certified: bool = bool(fields["certified"])
        self.global_solves: int = int(fields.get("global_solves", 0))


class DesignDirect(_JsonView):
    """The direct optimiser's additions (all at once) and their worst viewpoint."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.method: Optional[str] = _text(fields.get("method"))
        self.pbar_min: float = _float(fields.get("pbar_min"))
        self.added: FloatArray = _rows(fields.get("added"))
        self.worst_viewpoints: FloatArray = _rows(fields.get("worst_viewpoints"))
        self.max_worst_case_error_deg: float = _float(fields.get("max_worst_case_error_deg"))
        self.certified: bool = bool(fields.get("certified", False))
        self.global_solves: int = int(fields.get("global_solves", 0))


class DesignCoplanarity(_JsonView):
    """The data vectors' smallest singular value before and after the additions."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.initial: float = _float(fields["initial"])
        self.final: float = _float(fields["final"])
        self.nearly_coplanar: bool = bool(fields["nearly_coplanar"])
        self.threshold: float = _float(fields["threshold"])


class DesignResult(_JsonView):
    """vantage.design (``vantage design --json``); ``augmented`` is the new vantage.Layout (the
    CLI's --out file)."""

    def __init__(self, fields: Mapping[str, Any], augmented: Optional[Layout]) -> None:
        super().__init__(fields)
        #: The layout with the additions (None when design failed: NumericalError.result).
        self.augmented: Optional[Layout] = augmented
        self.layout: Optional[str] = _text(fields.get("layout"))
        self.name: str = str(fields["name"])
        self.mode: str = str(fields["mode"])
        self.status: str = str(fields["status"])
        self.message: Optional[str] = _text(fields.get("message"))
        self.initial = DesignState(fields["initial"])
        self.steps: List[DesignStep] = [DesignStep(s) for s in fields["steps"]]
        self.final_pbar_min: float = _float(fields["final_pbar_min"])
        self.direct: Optional[DesignDirect] = (
            DesignDirect(fields["direct"]) if isinstance(fields.get("direct"), dict) else None)
        self.coplanarity = DesignCoplanarity(fields["coplanarity"])
        self.global_solves: int = int(fields["global_solves"])
        #: The min_distance_difference= of the run (0: none).
        self.min_distance_difference: float = _float(fields["min_distance_difference"])
        #: Point layouts: Eq. (24.1) of the final markers (nan with fewer than two pairs);
        #: None for direction layouts.
        self.final_distance_difference: Optional[float] = (
            _float(fields["final_distance_difference"])
            if "final_distance_difference" in fields else None)


class WeightsSuggestion(_JsonView):
    """A way to make the layout balanced (Eq. 11): an entry to add and the weights then."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.kind: str = str(fields["kind"])
        self.text: str = str(fields["text"])
        self.added: FloatArray = _floats(fields.get("added"))
        self.min_weight: float = _float(fields.get("min_weight"))
        self.weights: FloatArray = _floats(fields.get("weights"))


class WeightsResult(_JsonView):
    """vantage.weights (``vantage weights --json``): non-negative w with sum_i w_i z_i = 0."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.layout: Optional[str] = _text(fields.get("layout"))
        self.mode: str = str(fields["mode"])
        self.n: int = int(fields["n"])
        self.feasible: bool = bool(fields["feasible"])
        self.status: str = str(fields["status"])
        self.weights: FloatArray = _floats(fields["weights"])
        self.residual: float = _float(fields["residual"])
        self.min_weight: float = _float(fields["min_weight"])
        self.lp_optimum: float = _float(fields["lp_optimum"])
        self.suggestion: Optional[WeightsSuggestion] = (
            WeightsSuggestion(fields["suggestion"]) if fields.get("suggestion") else None)
        self.suggestions: List[WeightsSuggestion] = [
            WeightsSuggestion(s) for s in fields.get("suggestions", [])]
        self.message: Optional[str] = _text(fields.get("message"))


# ------------------------------------------------------------------------------------- simulate


class Statistic(_JsonView):
    """Median, mean, 95th percentile and maximum of `count` values (nan when count is 0)."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.median: float = _float(fields["median"])
        self.mean: float = _float(fields["mean"])
        self.p95: float = _float(fields["p95"])
        self.max: float = _float(fields["max"])
        self.count: int = int(fields["count"])


class EstimatorStats(_JsonView):
    """One estimator over the Monte Carlo trials: error statistics, failures by status."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.trials: int = int(fields["trials"])
        self.rot_err_deg = Statistic(fields["rot_err_deg"])
        self.trans_err = Statistic(fields["trans_err"])
        self.trans_err_rel = Statistic(fields["trans_err_rel"])
        self.trans_err_deg = Statistic(fields["trans_err_deg"])
        self.scale_err = Statistic(fields["scale_err"])
        self.time_us = Statistic(fields["time_us"])
        self.failures: int = int(fields["failures"])
        self.by_status: Dict[str, int] = {k: int(v) for k, v in fields["by_status"].items()}
        self.wrong_but_ok: int = int(fields["wrong_but_ok"])


class BoundCheck(_JsonView):
    """The check of Eq. (26) / Eq. (30) on the affine camera over the trials."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.trials: int = int(fields["trials"])
        self.vectors: int = int(fields["vectors"])
        self.max_error_deg: float = _float(fields["max_error_deg"])
        self.bound_deg: float = _float(fields["bound_deg"])
        self.pbar_min: float = _float(fields["pbar_min"])
        self.max_ratio: float = _float(fields["max_ratio"])
        self.passed: bool = bool(fields["passed"])
        self.message: str = str(fields.get("message", ""))


class SimulationVisibility(_JsonView):
    """The simulation on the body (``vantage simulate --json`` "visibility"): views drawn from
    the trackable directions, images of the visible markers only, and (affine camera) the bound
    check against each view's p-bar and the certified p-bar_min under visibility. The check's
    fields are nan (passed True) when bound_checked is False (pinhole camera)."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.model: str = str(fields["model"])
        self.min_visible: int = int(fields["min_visible"])
        self.workspace: Optional[Workspace] = _workspace(fields["workspace"])
        self.occlusion_resolution_deg: Optional[float] = (
            None if fields["occlusion_resolution_deg"] is None
            else _float(fields["occlusion_resolution_deg"]))
        self.trackable_fraction: float = _float(fields["trackable_fraction"])
        self.coverage_samples: int = int(fields["coverage_samples"])
        self.worst_viewpoint: FloatArray = _floats(fields["worst_viewpoint"])
        self.worst_visible_markers: IntArray = _ints(fields["worst_visible_markers"])
        self.t_upper: float = _float(fields["t_upper"])
        self.t_lower: float = _float(fields["t_lower"])
        self.pbar_min: float = _float(fields["pbar_min"])
        self.bound_deg: float = _float(fields["bound_deg"])
        self.trials: int = int(fields["trials"])
        self.draws: int = int(fields["draws"])
        self.visible_markers = Statistic(fields["visible_markers"])
        self.max_view_t: float = _float(fields["max_view_t"])
        self.bound_checked: bool = bool(fields["bound_checked"])
        self.max_error_deg: float = _float(fields.get("max_error_deg"))
        self.max_ratio: float = _float(fields.get("max_ratio"))
        self.max_view_ratio: float = _float(fields.get("max_view_ratio"))
        self.max_view_excess_over_tolerance: float = _float(
            fields.get("max_view_excess_over_tolerance"))
        self.passed: bool = bool(fields.get("passed", True))
        self.message: str = str(fields.get("message", ""))


class SimulationReport(_JsonView):
    """vantage.simulate (``vantage simulate --json``): the estimators' statistics by name."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.layout: str = str(fields["layout"])
        self.mode: str = str(fields["mode"])
        self.trials: int = int(fields["trials"])
        self.total_trials: int = int(fields["total_trials"])
        self.seed: int = int(fields["seed"])
        self.estimators: Dict[str, EstimatorStats] = {
            name: EstimatorStats(stats) for name, stats in fields["estimators"].items()}
        self.bound_check: Optional[BoundCheck] = (
            BoundCheck(fields["bound_check"]) if isinstance(fields.get("bound_check"), dict)
            else None)
        self.visibility: Optional[SimulationVisibility] = (
            SimulationVisibility(fields["visibility"]) if "visibility" in fields else None)
        self.config: Dict[str, Any] = copy.deepcopy(fields["config"])
        self.per_trial: Optional[PerTrial] = (
            PerTrial(fields["per_trial"]) if "per_trial" in fields else None)


class PerTrial(_JsonView):
    """Every trial's values (per_trial=True): trial numbers and, per estimator and field, one
    entry per trial (numbers as float arrays with nan for null; status strings, ok booleans
    as arrays too)."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.trial: IntArray = _ints(fields["trial"])
        self.estimators: Dict[str, Dict[str, npt.NDArray[Any]]] = {
            name: {key: _column(values) for key, values in columns.items()}
            for name, columns in fields["estimators"].items()}


def _column(values: List[Any]) -> npt.NDArray[Any]:
    if values and all(isinstance(v, (bool, str)) for v in values):
        return np.asarray(values)
    return _floats(values)
