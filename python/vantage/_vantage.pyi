# Type stubs of the compiled module vantage._vantage (python/src/*.cc). The public functions
# that return results are wrapped in vantage/__init__.py, which has the typed signatures users
# call; this stub describes what the extension itself takes and returns.
import os
from typing import Any, Dict, Iterable, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str

_Path = Union[str, "os.PathLike[str]"]
_Array = Optional[npt.ArrayLike]

class NumericalError(RuntimeError):
    status: str
    message: str
    result: Any
    text: str

class Layout:
    def __init__(self, *, vectors: _Array = None, points: _Array = None,
                 weights: _Array = None, candidates: _Array = None,
                 names: Optional[Sequence[str]] = None, name: str = "",
                 description: str = "", normals: _Array = None,
                 visibility: Optional[Mapping[str, Any]] = None,
                 workspace: Optional[Mapping[str, Any]] = None) -> None: ...
    @property
    def name(self) -> str: ...
    @property
    def names(self) -> List[str]: ...
    @property
    def description(self) -> str: ...
    @property
    def mode(self) -> str: ...
    @property
    def entries(self) -> npt.NDArray[np.float64]: ...
    @property
    def weights(self) -> npt.NDArray[np.float64]: ...
    @property
    def candidates(self) -> npt.NDArray[np.float64]: ...
    @property
    def normals(self) -> Optional[npt.NDArray[np.float64]]: ...
    def to_dict(self) -> Dict[str, Any]: ...
    def __len__(self) -> int: ...

def load_layout(path: _Path, *, format: Optional[str] = None, tag_points: Optional[str] = None,
                bundle: Optional[str] = None, allow_large: bool = False) -> Layout: ...
def save_layout(layout: Layout, path: _Path, *, overwrite: bool = False) -> None: ...
def board(type: str, *, rows: int, cols: int, square: float, marker: float = 0.0,
          spacing: float = 0.3) -> Layout: ...
def data_vectors(layout: Layout, *, pair_weighting: str = "geometric"
                 ) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
def pbar_at_viewpoints(vectors: npt.ArrayLike,
                       viewpoints: npt.ArrayLike) -> npt.NDArray[np.float64]: ...
def pose_methods() -> List[str]: ...
def load_correspondences(path: _Path) -> Dict[str, Any]: ...

def analyze(layout: Union[Layout, _Path, None] = None, *, vectors: _Array = None,
            points: _Array = None, weights: _Array = None, swaps: int = 5,
            crosscheck: bool = True, pair_weighting: str = "geometric", dropout: bool = False,
            allow_large: bool = False, format: Optional[str] = None,
            tag_points: Optional[str] = None,
            bundle: Optional[str] = None) -> Tuple[Dict[str, Any], str]: ...
def design(layout: Union[Layout, _Path, None] = None, *, vectors: _Array = None,
           points: _Array = None, weights: _Array = None, candidates: _Array = None,
           add: int = 1, candidates_only: bool = False, margin: float = 0.25,
           direct: bool = True, min_distance_difference: float = 0.0,
           allow_large: bool = False, format: Optional[str] = None,
           tag_points: Optional[str] = None, bundle: Optional[str] = None,
           objective: str = "affine", distance: Optional[float] = None,
           distances: Optional[Sequence[float]] = None, focal: Optional[float] = None,
           noise_px: Optional[float] = None, statistic: str = "worst",
           crb_samples: Optional[int] = None, aim: Optional[Sequence[float]] = None,
           targets: Optional[Any] = None, fle_rms: Optional[float] = None,
           fle_sigma: Optional[Sequence[float]] = None) -> Dict[str, Any]: ...
def weights(layout: Union[Layout, _Path, None] = None, *, vectors: _Array = None,
            points: _Array = None, allow_large: bool = False, format: Optional[str] = None,
            tag_points: Optional[str] = None, bundle: Optional[str] = None) -> Dict[str, Any]: ...
def pose(model: _Array = None, image: _Array = None, *, method: str = "affine",
         measured: _Array = None, image1: _Array = None, image2: _Array = None,
         weights: _Array = None, focal: Optional[float] = None, principal_point: _Array = None,
         free_vectors: Optional[str] = None) -> Dict[str, Any]: ...
def orient(model: npt.ArrayLike, measured: npt.ArrayLike, *, weights: _Array = None,
           method: str = "qmethod") -> Dict[str, Any]: ...
def crb(layout: Union[Layout, _Path, None] = None, *, points: _Array = None,
        distance: float, focal: float, noise_px: float, principal_point: _Array = None,
        direction: _Array = None, sweep_distance: Optional[Tuple[float, float, int]] = None,
        samples: int = 10000, threads: int = 0, allow_large: bool = False,
        format: Optional[str] = None, tag_points: Optional[str] = None,
        bundle: Optional[str] = None, aim: Optional[Sequence[float]] = None) -> Dict[str, Any]: ...
def tre(layout: Union[Layout, _Path, None] = None, *, points: _Array = None,
        targets: _Array = None, fle_rms: Optional[float] = None,
        fle_sigma: Optional[Tuple[float, float]] = None, direction: _Array = None,
        monte_carlo: int = 0, seed: int = 1, threads: int = 0, allow_large: bool = False,
        format: Optional[str] = None, tag_points: Optional[str] = None,
        bundle: Optional[str] = None) -> Dict[str, Any]: ...
def simulate(layout: Union[Layout, _Path, None] = None, *, vectors: _Array = None,
             points: _Array = None, trials: int = 1000, camera: str = "affine",
             noise_px: float = 0.0, snr_db: Optional[float] = None, noise: str = "gaussian",
             range: float = 10.0, focal_px: float = 1000.0,
             principal_point: Sequence[float] = ..., lateral_offset: Sequence[float] = ...,
             viewpoint: str = "random", methods: Sequence[str] = ..., seed: int = 1,
             threads: int = 0, per_trial: bool = False, allow_large: bool = False,
             format: Optional[str] = None, tag_points: Optional[str] = None,
             bundle: Optional[str] = None) -> Dict[str, Any]: ...
def ident(tools: Iterable[Union[Layout, _Path]], *, min_visible: Optional[int] = None,
          same_tolerance: float = 0.01, format: Optional[str] = None,
          allow_large: bool = False) -> Dict[str, Any]: ...
def place(body: Optional[_Path] = None, *, sites: Optional[_Path] = None, markers: int,
          candidates: Optional[int] = None, cone_deg: Optional[float] = None,
          min_visible: Optional[int] = None,
          workspace: Optional[Tuple[float, float, float, float]] = None,
          min_separation: Optional[float] = None, keep: Optional[_Path] = None,
          robust_dropout: bool = False, min_distance_difference: float = 0.0,
          seed: Optional[int] = None, threads: Optional[int] = None,
          random_trials: Optional[int] = None, exhaustive_limit: Optional[int] = None,
          out: Optional[_Path] = None, overwrite: bool = False, objective: str = "affine",
          distance: Optional[float] = None, distances: Optional[Sequence[float]] = None,
          focal: Optional[float] = None, noise_px: Optional[float] = None,
          statistic: str = "worst",
          crb_samples: Optional[int] = None, aim: Optional[Sequence[float]] = None,
          targets: Optional[Any] = None, fle_rms: Optional[float] = None,
          fle_sigma: Optional[Sequence[float]] = None, min_coverage: Optional[float] = None,
          allow_partial: bool = False, marker_diameter: float = 0.0,
          exclude: Union[None, _Path, Sequence[_Path]] = None,
          region: Optional[_Path] = None, perturbations: int = 0) -> Dict[str, Any]: ...
