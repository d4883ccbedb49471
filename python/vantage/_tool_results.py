"""Typed results of the camera and tracker commands: ``vantage crb``, ``vantage tre``,
``vantage ident`` and ``vantage place``. As in ``_results``, each class is a view of the one JSON
object the subcommand prints with ``--json``, written by the C++ library's own JSON writer.
"""

from __future__ import annotations

import math
from typing import Any, Dict, List, Mapping, Optional

import numpy as np

from ._results import (FloatArray, IntArray, LayoutVisibility, _float, _floats, _ints, _JsonView,
                       _text)
from ._vantage import Layout

__all__ = [
    "CrbBound", "CrbReport", "CrbSweepRow", "DesignSensorResult", "IdentPair", "IdentReport",
    "IdentTool", "PlaceBaseline", "PlaceReport", "PlaceRobust", "PlaceStep", "TreAtDirection", "TreExtreme",
    "TreMonteCarlo", "TreReport", "TreTarget",
]


def _optional_float(value: Any) -> Optional[float]:
    return None if value is None else float(value)


class CrbBound(_JsonView):
    """The pose CRB at one viewing direction (``vantage crb --json``'s ``worst``, ``best``,
    ``at_direction``; C++ camera::PoseCrbAt). rot_rms_deg and trans_rms are None when the
    direction is not trackable; ``unbounded`` when it sees enough markers but the first-order
    bound means nothing there (F singular, or rot_rms past 45 degrees: no figure);
    ``covariance`` (6 x 6, ROS order x, y, z, rx, ry, rz, camera frame) only for
    ``at_direction``.
    """

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.direction: FloatArray = _floats(fields["direction"])
        self.trackable: bool = bool(fields["trackable"])
        self.unbounded: bool = bool(fields["unbounded"])
        self.rot_rms_deg: Optional[float] = _optional_float(fields["rot_rms_deg"])
        self.trans_rms: Optional[float] = _optional_float(fields["trans_rms"])
        self.visible_markers: IntArray = _ints(fields["visible_markers"])
        cov = fields.get("covariance")
        self.covariance: Optional[FloatArray] = (
            None if cov is None else np.asarray(cov, dtype=np.float64))


class CrbSweepRow(_JsonView):
    """One distance of ``--sweep-distance``: the worst and the median direction there."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.distance: float = _float(fields["distance"])
        self.trackable_fraction: float = _float(fields["trackable_fraction"])
        self.unbounded_fraction: float = _float(fields["unbounded_fraction"])
        self.worst: Optional[CrbBound] = (
            None if fields["worst"] is None else CrbBound(fields["worst"]))
        self.median: Optional[CrbBound] = (
            None if fields["median"] is None else CrbBound(fields["median"]))


class CrbReport(_JsonView):
    """The pose Cramér–Rao bound over every viewpoint (``vantage crb --json``; C++
    camera::PoseCrbReport; docs/math.md §22). status is 'ok', 'untrackable', 'ill_conditioned'
    or 'unbounded' (then ``message`` says why; None when ok). ``unbounded_fraction``: the part of
    the workspace where the first-order bound is unbounded; worst, best and percentiles are over
    the trackable rest, and ``worst.unbounded`` when the bound passes 45 degrees anywhere the
    search reaches."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.camera: Dict[str, Any] = dict(fields["camera"])
        self.markers: int = int(fields["markers"])
        self.status: str = str(fields["status"])
        self.message: Optional[str] = _text(fields.get("message"))
        self.at_direction: Optional[CrbBound] = (
            CrbBound(fields["at_direction"]) if "at_direction" in fields else None)
        self.worst: Optional[CrbBound] = (
            None if fields["worst"] is None else CrbBound(fields["worst"]))
        self.best: Optional[CrbBound] = None if fields["best"] is None else CrbBound(fields["best"])
        self.trackable_fraction: float = _float(fields["trackable_fraction"])
        self.unbounded_fraction: float = _float(fields["unbounded_fraction"])
        self.percentiles: Dict[str, Optional[float]] = {
            k: _optional_float(v) for k, v in fields["percentiles"].items()}
        self.sliver: bool = bool(fields["sliver"])
        self.worst_region_width_deg: float = _float(fields["worst_region_width_deg"])
        self.affine_bound_deg: float = _float(fields["affine_bound_deg"])
        self.sweep_distance: Optional[List[CrbSweepRow]] = (
            [CrbSweepRow(r) for r in fields["sweep_distance"]]
            if "sweep_distance" in fields else None)


class TreExtreme(_JsonView):
    """The worst or best RMS TRE over the tracked lines of sight (``vantage tre --json``'s
    ``worst``, ``best``; C++ tracker::TreExtreme). direction and rms are nan when no line of sight
    is tracked (status 'untracked'); rms_bound is the proven bound, certified when every patch
    closed."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.direction: FloatArray = (
            np.full(3, math.nan) if fields["direction"] is None else _floats(fields["direction"]))
        self.rms: float = _float(fields["rms"])
        self.visible_markers: IntArray = _ints(fields["visible_markers"])
        self.certified: bool = bool(fields["certified"])
        self.status: str = str(fields["status"])
        self.rms_bound: float = _float(fields["rms_bound"])
        self.patches: int = int(fields["patches"])
        self.closed_form: bool = bool(fields["closed_form"])


class TreAtDirection(_JsonView):
    """The TRE at the given line of sight (``at_direction``; C++ tracker::TreAtDirection): rms (nan
    when not tracked) and its 3 x 3 covariance in the tool frame (None when not tracked)."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.direction: FloatArray = _floats(fields["direction"])
        self.tracked: bool = bool(fields["tracked"])
        self.rms: float = _float(fields["rms"])
        cov = fields["covariance"]
        self.covariance: Optional[FloatArray] = (
            None if cov is None else np.asarray(cov, dtype=np.float64))
        self.visible_markers: IntArray = _ints(fields["visible_markers"])


class TreMonteCarlo(_JsonView):
    """The Monte Carlo check (``monte_carlo``): the measured RMS of ``trials`` registrations at
    ``direction`` beside the first-order formula, rel_diff = rms / formula_rms - 1."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.trials: int = int(fields["trials"])
        self.rms: float = _float(fields["rms"])
        self.formula_rms: float = _float(fields["formula_rms"])
        self.rel_diff: float = _float(fields["rel_diff"])
        self.direction: FloatArray = _floats(fields["direction"])


class TreTarget(_JsonView):
    """One target's TRE (an entry of ``targets``; C++ tracker::TreTargetReport)."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.target: FloatArray = _floats(fields["target"])
        self.rms_isotropic: Optional[float] = _optional_float(fields.get("rms_isotropic"))
        self.at_direction: Optional[TreAtDirection] = (
            TreAtDirection(fields["at_direction"]) if "at_direction" in fields else None)
        self.worst: TreExtreme = TreExtreme(fields["worst"])
        self.best: TreExtreme = TreExtreme(fields["best"])
        self.monte_carlo: Optional[TreMonteCarlo] = (
            TreMonteCarlo(fields["monte_carlo"]) if "monte_carlo" in fields else None)


class TreReport(_JsonView):
    """The target registration error of a tool on a 3-D tracker (``vantage tre --json``; C++
    tracker::TreReport; docs/math.md §23): per target, Fitzpatrick's isotropic RMS, the TRE at a line
    of sight, the certified worst and best over the tracked lines of sight, Monte Carlo."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.targets: List[TreTarget] = [TreTarget(t) for t in fields["targets"]]
        self.fle: Dict[str, Any] = dict(fields["fle"])
        self.model: Dict[str, Any] = dict(fields["model"])


# ------------------------------------------------------------------ tool identification (ident)


class IdentTool(_JsonView):
    """One tool of ``vantage ident --json``'s ``tools``: its file (None for a vantage.Layout),
    name, number of markers and ``min_visible``, the k of its views (its own minimum, or the
    ``min_visible`` given)."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.file: Optional[str] = _text(fields["file"])
        self.name: str = str(fields["name"])
        self.markers: int = int(fields["markers"])
        self.min_visible: int = int(fields["min_visible"])


class IdentPair(_JsonView):
    """One pair of tools a <= b (a == b: the tool against itself relabelled; C++
    vantage::tracker::ToolPairMatch): the mismatch of Eq. (24.4), the view ``subset`` of tool a and the
    markers ``assignment`` of tool b that give it (indices, and names), the best rigid fit
    ('rotation', 'reflection' or 'either') with the RMS of each, and whether the search ended
    within its budget (else ``mismatch_lower`` bounds what it left); ``verdict``: 'self',
    'same_tool', 'mirror' or 'distinct'; ``min_visible``: the k of the match (the smaller of the
    two tools')."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.a: int = int(fields["a"])
        self.b: int = int(fields["b"])
        self.self: bool = bool(fields["self"])
        self.verdict: str = str(fields["verdict"])
        self.min_visible: int = int(fields["min_visible"])
        self.mismatch: float = _float(fields["mismatch"])
        self.subset: IntArray = _ints(fields["subset"])
        self.assignment: IntArray = _ints(fields["assignment"])
        self.subset_names: List[str] = [str(n) for n in fields["subset_names"]]
        self.assignment_names: List[str] = [str(n) for n in fields["assignment_names"]]
        self.transform: str = str(fields["transform"])
        self.proper_rms: float = _float(fields["proper_rms"])
        self.improper_rms: float = _float(fields["improper_rms"])
        self.certified: bool = bool(fields["certified"])
        self.mismatch_lower: float = _float(fields["mismatch_lower"])
        self.comparisons: int = int(fields["comparisons"])


class IdentReport(_JsonView):
    """vantage.ident (``vantage ident --json``; C++ vantage::tracker::ToolLibraryMatches; docs/math.md
    §24): the tools, every pair (each unordered pair once, self pairs included), the closest
    pair and the closest pair of distinct tools (entries of ``pairs``; None when no pair is
    distinct), the n x n ``matrix`` of mismatches, and ``min_visible``, the k every tool shares
    (None when the tools' own minima differ)."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        shared = fields["min_visible"]
        self.min_visible: Optional[int] = None if shared is None else int(shared)
        self.tools: List[IdentTool] = [IdentTool(t) for t in fields["tools"]]
        self.pairs: List[IdentPair] = [IdentPair(p) for p in fields["pairs"]]
        self.closest: IdentPair = self._pair(fields["closest"])
        distinct = fields["closest_distinct"]
        self.closest_distinct: Optional[IdentPair] = (
            None if distinct is None else self._pair(distinct))
        self.matrix: FloatArray = _floats(fields["matrix"]).reshape(len(self.tools),
                                                                    len(self.tools))
        self.certified: bool = bool(fields["certified"])

    def _pair(self, summary: Mapping[str, Any]) -> IdentPair:
        return next(p for p in self.pairs if (p.a, p.b) == (summary["a"], summary["b"]))


# ------------------------------------------------------------------- marker placement (place)


class PlaceStep(_JsonView):
    """One greedy step of ``vantage place --json``'s ``steps``: k markers after adding site
    ``added`` (-1 for the kept markers), their coverage and certified p-bar_min."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.k: int = int(fields["k"])
        self.added: int = int(fields["added"])
        self.coverage: float = _float(fields["coverage"])
        self.pbar_min: float = _float(fields["pbar_min"])


class PlaceBaseline(_JsonView):
    """The random baseline: ``trials`` random feasible K-subsets, ``complete`` of them trackable
    everywhere, the best one's coverage and p-bar_min and the median p-bar_min."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.trials: int = int(fields["trials"])
        self.complete: int = int(fields["complete"])
        self.best_coverage: float = _float(fields["best_coverage"])
        self.best_pbar_min: float = _float(fields["best_pbar_min"])
        self.median_pbar_min: float = _float(fields["median_pbar_min"])


class PlaceRobust(_JsonView):
    """robust_dropout=True: the worst p-bar_min over the loss of any one chosen marker, that
    marker (its candidate index, -1 for a kept one, and name) and the coverage then."""

    def __init__(self, fields: Mapping[str, Any]) -> None:
        super().__init__(fields)
        self.pbar_min: float = _float(fields["pbar_min"])
        self.worst_lost_marker: int = int(fields["worst_lost_marker"])
        self.worst_lost_name: str = str(fields["worst_lost_name"])
        self.coverage: float = _float(fields["coverage"])


class PlaceReport(_JsonView):
    """vantage.place (``vantage place --json``; C++ design::PlacementResult; docs/math.md §21):
    the chosen candidate indices and kept markers' names, how they were found (``search``
    'greedy' or 'exhaustive'), the placed layout's analysis on its body (``visibility``, as
    vantage.analyze), the random baseline and the greedy steps. ``layout`` is the placed
    vantage.Layout (the CLI's --out file); ``written`` the file it was written to, or None."""

    def __init__(self, fields: Mapping[str, Any], layout: Optional[Layout]) -> None:
        super().__init__(fields)
        #: The placed layout; on a NumericalError, the best (incomplete) answer found.
        self.layout: Optional[Layout] = layout
        self.sites: str = str(fields["sites"])
        self.status: str = str(fields["status"])
        self.chosen: IntArray = _ints(fields["chosen"])
        self.kept: List[str] = [str(k) for k in fields["kept"]]
        self.n_candidates: int = int(fields["n_candidates"])
        #: Sampled on a body mesh: the samples drawn; None for a sites file.
        self.drawn: Optional[int] = int(fields["drawn"]) if "drawn" in fields else None
        #: Sampled on a body mesh: the sampled sites the exclude volumes dropped; None for a
        #: sites file.
        self.excluded: Optional[int] = int(fields["excluded"]) if "excluded" in fields else None
        self.markers: int = int(fields["markers"])
        self.search: str = str(fields["search"])
        visibility = fields["visibility"]
        self.visibility: Optional[LayoutVisibility] = (
            None if visibility is None else LayoutVisibility(visibility))
        self.coverage: float = _float(fields["coverage"])
        self.pbar_min: float = _float(fields["pbar_min"])
        self.random_baseline = PlaceBaseline(fields["random_baseline"])
        #: The objective (``--json``'s "objective"): its name, its value on the placed layout as
        #: ``vantage analyze``, ``crb`` or ``tre`` reports it ("value_deg", or "value" in the
        #: layout's unit for 'tracker'), and its settings.
        self.objective: Dict[str, Any] = dict(fields["objective"])
        self.steps: List[PlaceStep] = [PlaceStep(s) for s in fields["steps"]]
        self.robust: Optional[PlaceRobust] = (
            PlaceRobust(fields["robust"]) if "robust" in fields else None)
        self.swaps: int = int(fields["swaps"])
        #: search 'greedy+swap': the perturbation rounds asked for and those that improved the
        #: answer; else None.
        self.perturbations: Optional[int] = (
            int(fields["perturbations"]) if "perturbations" in fields else None)
        self.improving_perturbations: Optional[int] = (
            int(fields["improving_perturbations"]) if "improving_perturbations" in fields
            else None)
        self.evaluations: int = int(fields["evaluations"])
        #: search 'exhaustive': the feasible subsets searched; else None.
        self.subsets: Optional[int] = int(fields["subsets"]) if "subsets" in fields else None
        covering = fields.get("covering_markers")
        #: Incomplete placements: the markers greedy by coverage needs to cover the workspace
        #: (None when it cannot) and what all sites together cover.
        self.covering_markers: Optional[int] = None if covering is None else int(covering)
        self.all_sites_coverage: Optional[float] = (
            _float(fields["all_sites_coverage"]) if "all_sites_coverage" in fields else None)
        self.written: Optional[str] = _text(fields["written"])


class DesignSensorResult(_JsonView):
    """vantage.design(objective='camera' or 'tracker') (``vantage design --objective ...
    --json``; docs/math.md §21, "In design"): the candidates added (``added``, indices into the
    layout's candidates) by place's search (``search`` 'exhaustive' or 'greedy+swap') on the
    layout seen whole, the greedy ``steps``, the ``random_baseline``, and the sensor's value of
    the layout before (``initial``, None with fewer than 3 markers) and of ``augmented``
    (``sensor``, as vantage.analyze reports it on that layout: "value_deg" for a camera, "value"
    in the layout's unit for a tracker). ``augmented`` is the new vantage.Layout, with the sensor
    block; ``written`` is None (Python writes no file)."""

    def __init__(self, fields: Mapping[str, Any], augmented: Optional[Layout]) -> None:
        super().__init__(fields)
        #: The augmented layout; on a NumericalError, the best (incomplete) answer found.
        self.augmented: Optional[Layout] = augmented
        self.objective: str = str(fields["objective"])
        self.status: str = str(fields["status"])
        self.complete: bool = bool(fields["complete"])
        self.markers: int = int(fields["markers"])
        self.candidates: int = int(fields["candidates"])
        self.added: IntArray = _ints(fields["added"])
        self.search: str = str(fields["search"])
        key = "value_deg" if self.objective == "camera" else "value"
        #: The value the search ranked by (the camera's before the refinement of its worst).
        self.search_value: float = _float(fields["search_" + key])
        self.evaluations: int = int(fields["evaluations"])
        #: search 'exhaustive': the subsets searched; else None.
        self.subsets: Optional[int] = int(fields["subsets"]) if "subsets" in fields else None
        #: search 'greedy+swap': the improving swaps; else None.
        self.swaps: Optional[int] = int(fields["swaps"]) if "swaps" in fields else None
        #: Each greedy step: k, the candidate added (None for the kept markers' row), the
        #: coverage and the search value ("value_deg" or "value"; None when incomplete).
        self.steps: List[Dict[str, Any]] = [dict(step) for step in fields["steps"]]
        self.random_baseline: Dict[str, Any] = dict(fields["random_baseline"])
        initial = fields["initial"]
        self.initial: Optional[Dict[str, Any]] = None if initial is None else dict(initial)
        self.sensor: Dict[str, Any] = dict(fields["sensor"])
        #: The value of ``augmented`` (``sensor``'s "value_deg" or "value"; nan when none).
        self.value: float = _float(self.sensor.get(key))
        self.written: Optional[str] = _text(fields["written"])
