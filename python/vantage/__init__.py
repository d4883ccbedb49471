"""vantage: evaluate and design fiducial layouts for pose from a single affine image.

Thin bindings over the C++ libraries; every function returns what the matching ``vantage``
subcommand prints with ``--json``, as a :class:`Result` whose attributes are the JSON fields.

Arrays are numpy, one point or vector per row: layouts and models are ``n x 3``, image points
``n x 2``. Any numeric dtype (float32, int) is converted to float64; a ``3 x n`` array is
rejected with a message telling you to pass its transpose.

Errors: bad input raises ``ValueError`` with the CLI's message (file, field, index);
a computation that finished but failed numerically (the CLI's exit status 1) raises
:class:`NumericalError` with ``status``, ``message`` and the full ``result``.
"""

import numpy as _np

from ._vantage import (  # noqa: F401
    Layout,
    NumericalError,
    __version__,
    board,
    data_vectors,
    load_correspondences,
    load_layout,
    pbar_at_viewpoints,
    pose_methods,
    save_layout,
)
from . import _vantage

__all__ = [
    "Layout", "NumericalError", "Result", "analyze", "board", "data_vectors", "design",
    "load_correspondences", "load_layout", "orient", "pbar_at_viewpoints", "pose",
    "pose_methods", "save_layout", "simulate", "weights", "__version__",
]


def _numeric_list(value):
    """True for a (nested) list of numbers of rectangular shape."""
    if not isinstance(value, list) or not value:
        return False
    try:
        array = _np.asarray(value)
    except ValueError:
        return False
    return array.dtype.kind in "fiu"


class Result:
    """A result: attributes are the JSON fields of the matching CLI subcommand.

    Numeric lists come back as numpy arrays (lists of points as ``n x 3``), nested objects as
    Result, lists of objects as lists of Result. ``to_dict()`` gives the plain JSON-style dict.
    """

    def __init__(self, fields):
        self._fields = fields

    def __getattr__(self, name):
        fields = self.__dict__.get("_fields", {})
        if name not in fields:
            raise AttributeError(f"result has no field {name!r}; fields: {', '.join(fields)}")
        return _wrap(fields[name])

    def __getitem__(self, name):
        return _wrap(self._fields[name])

    def __contains__(self, name):
        return name in self._fields

    def __dir__(self):
        return list(self._fields)

    def keys(self):
        return self._fields.keys()

    def to_dict(self):
        """The fields as plain Python (dicts, lists, numbers, strings, None)."""
        return {k: _plain(v) for k, v in self._fields.items()}

    def __repr__(self):
        shown = ", ".join(f"{k}={_short(v)}" for k, v in self._fields.items())
        return f"Result({shown})"


def _wrap(value):
    if isinstance(value, dict):
        return Result(value)
    if _numeric_list(value):
        return _np.asarray(value)
    if isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
        return [Result(v) for v in value]
    return value


def _plain(value):
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_plain(v) for v in value]
    return value


def _short(value):
    text = repr(value)
    return text if len(text) <= 40 else text[:37] + "..."


def _raising(function):
    def call(*args, **kwargs):
        try:
            return function(*args, **kwargs)
        except NumericalError as error:
            error.result = Result(error.result)
            raise
    call.__name__ = function.__name__
    call.__doc__ = function.__doc__
    return call


@_raising
def analyze(layout=None, **kwargs):
    return Result(_vantage.analyze(layout, **kwargs))


@_raising
def design(layout=None, **kwargs):
    fields = _vantage.design(layout, **kwargs)
    out = Result({k: v for k, v in fields.items() if k != "augmented"})
    out.__dict__["augmented"] = fields["augmented"]
    return out


@_raising
def weights(layout=None, **kwargs):
    return Result(_vantage.weights(layout, **kwargs))


@_raising
def pose(model=None, image=None, **kwargs):
    return Result(_vantage.pose(model, image, **kwargs))


@_raising
def orient(model, measured, **kwargs):
    return Result(_vantage.orient(model, measured, **kwargs))


@_raising
def simulate(layout=None, **kwargs):
    return Result(_vantage.simulate(layout, **kwargs))


for _name in ("analyze", "design", "weights", "pose", "orient", "simulate"):
    globals()[_name].__doc__ = getattr(_vantage, _name).__doc__
