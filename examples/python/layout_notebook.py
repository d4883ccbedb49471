"""vantage from Python, notebook style: load an AprilTag bundle, analyse it, map p-bar(a) over
the viewing sphere, and add a marker where the layout is weakest.

Run:  PYTHONPATH=build/python python3 examples/python/layout_notebook.py [--out DIR]
The figure needs matplotlib (Debian: python3-matplotlib); without it the plot is skipped.
Each "# %%" starts a cell (VS Code, Jupytext and Spyder run them one by one).
"""

# %% Setup
import argparse
import pathlib

import numpy as np

import vantage

HERE = pathlib.Path(__file__).resolve().parent
BUNDLE = HERE.parent / "layouts" / "apriltag_cube.yaml"

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("."),
                    help="directory for the figure and the augmented layout")
args = parser.parse_args()
args.out.mkdir(parents=True, exist_ok=True)

# %% Load the tags.yaml of the ROS AprilTag detector: markers = the 4 corners of every tag
layout = vantage.load_layout(BUNDLE)
print(layout, "- first corners (m):")
print(layout.entries[:4])

# %% How good is it? The global worst viewpoint (Theorem 6) and the worst-case error (Eq. 30)
result = vantage.analyze(layout)
print(f"p-bar_min = {result.pbar_min:.4f} (ceiling {result.ceiling:.4f} for "
      f"{result.n_vectors} free vectors), certified: {result.certificate.certified}")
print(f"worst viewpoint a = {np.round(result.worst_viewpoint, 4)}, "
      f"max worst-case error {result.max_worst_case_error_deg:.2f} deg")

# %% p-bar(a) over the viewing sphere (p-bar(a) = p-bar(-a): the upper hemisphere is enough)
vectors, _ = vantage.data_vectors(layout)
azimuth = np.radians(np.arange(0.0, 360.5, 1.0))
elevation = np.radians(np.arange(0.0, 90.5, 0.5))
az, el = np.meshgrid(azimuth, elevation)
viewpoints = np.stack([np.cos(el) * np.cos(az), np.cos(el) * np.sin(az), np.sin(el)], axis=-1)
pbar = vantage.pbar_at_viewpoints(vectors, viewpoints.reshape(-1, 3)).reshape(az.shape)
print(f"p-bar over {pbar.size} viewpoints: min {pbar.min():.4f} (the analysis: "
      f"{result.pbar_min:.4f}), max {pbar.max():.4f}")
assert pbar.min() >= result.pbar_min - 1e-9, "the certified minimum is a lower bound"

# %% Plot (only with matplotlib)
try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    plt = None
    print("matplotlib is not installed (Debian: python3-matplotlib): skipping the plot")

if plt is not None:
    fig, ax = plt.subplots(figsize=(8, 4.2), constrained_layout=True)
    mesh = ax.pcolormesh(np.degrees(az), np.degrees(el), pbar, shading="auto", cmap="viridis")
    fig.colorbar(mesh, ax=ax, label=r"$\bar p(a)$ (higher is better)")
    for a in result.worst_viewpoints:
        a = a if a[2] >= 0 else -a
        ax.plot(np.degrees(np.arctan2(a[1], a[0])) % 360, np.degrees(np.arcsin(a[2])), "r*",
                markersize=14, markeredgecolor="white")
    ax.set_xlabel("azimuth of the viewpoint a (deg)")
    ax.set_ylabel("elevation (deg)")
    ax.set_title(f"{layout.name}: $\\bar p$ over the viewing hemisphere; worst viewpoints "
                 f"(red stars) $\\bar p_{{min}}$ = {result.pbar_min:.3f}")
    figure = args.out / "pbar_sphere.png"
    fig.savefig(figure, dpi=120)
    print("figure:", figure)

# %% Make it better: add one marker where the worst viewpoint is weakest
better = vantage.design(layout, add=1, direct=False)
step = better.steps[0]
print(f"add a marker at {np.round(step.added, 4)}: p-bar_min {better.initial.pbar_min:.4f} -> "
      f"{step.pbar_min:.4f} ({step.note})")
out = args.out / "cube_plus_one.json"
vantage.save_layout(better.augmented, out, overwrite=True)
print("written:", out)
