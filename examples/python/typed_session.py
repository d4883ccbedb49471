"""A typed session with the installed package: the README's Python example, run by the install
test (python/tests/install_check.py) outside the source tree and checked there by mypy --strict.

    python3 examples/python/typed_session.py [EXAMPLES_DIR]

EXAMPLES_DIR holds layouts/ and correspondences/ (default: this repository's examples/).
"""

import pathlib
import sys

import numpy as np
import numpy.typing as npt

import vantage

examples = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parents[1])

# The layout report: typed attributes, numpy arrays, the library's brief report as repr().
report: vantage.LayoutReport = vantage.analyze(examples / "layouts" / "satellite.json",
                                               dropout=True)
print(report)
print(f"p-bar_min {report.pbar_min:.6f}, worst case {report.max_worst_case_error_deg:.3f} deg")
viewpoints: npt.NDArray[np.float64] = report.worst_viewpoints  # k x 3
assert viewpoints.shape[1] == 3 and report.certificate.certified and report.usable
assert report.dropout is not None
harm = max(report.dropout, key=lambda entry: entry.max_worst_case_error_deg)
print(f"losing marker {harm.index} costs the most: {harm.max_worst_case_error_deg:.3f} deg")
assert report.to_dict()["pbar_min"] == report.pbar_min  # to_dict() is the --json object

# The same layout from arrays, and the pose of known correspondences.
triad = vantage.analyze(vectors=np.eye(3))
assert abs(triad.pbar_min - np.sqrt(2.0 / 3.0)) < 1e-12
estimate: vantage.PoseEstimate = vantage.pose(
    **vantage.load_correspondences(examples / "correspondences" / "affine_pose.json"))
print(f"pose {estimate.method}: status {estimate.status}, "
      f"reprojection {estimate.reprojection_rms_px:.2e} px")
rotation: npt.NDArray[np.float64] = estimate.R
assert rotation.shape == (3, 3) and np.allclose(rotation @ rotation.T, np.eye(3), atol=1e-9)

# Bad input is a ValueError naming the argument; the size limits hold (allow_large=True lifts).
try:
    vantage.analyze(vectors=np.eye(3), weights=[1.0, -1.0, 1.0])
except ValueError as error:
    print(f"ValueError: {error} (field {error.field!r}, index {error.index})")  # type: ignore[attr-defined]
try:
    vantage.simulate(vectors=np.eye(3), trials=10**8)
except ValueError as error:
    print(f"ValueError: {error}")
