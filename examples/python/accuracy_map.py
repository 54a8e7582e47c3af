#!/usr/bin/env python3
# %% [markdown]
# # Accuracy map of a sensor preset, in a notebook
#
# The range accuracy over a signal x background grid (thesis Fig. 3.4) and where range can be
# derived at all (Fig. 3.3), straight from `rangesim.evaluate` as NumPy arrays, no files or CSV
# in between. Run it as a script, or cell by cell (`# %%`) in Jupyter or VS Code:
#
#     PYTHONPATH=build/python python3 examples/python/accuracy_map.py [SENSOR] [--out DIR]
#         [--points N] [--set KEY=VALUE ...]
#
# With matplotlib (Debian: python3-matplotlib) it draws DIR/accuracy_map.png; without, it writes
# the arrays to DIR/accuracy_map.npz and says so.

# %%
import argparse
import os

import numpy as np

import rangesim

ap = argparse.ArgumentParser(description="accuracy map of a rangesim preset")
ap.add_argument("sensor", nargs="?", default="ls-conventional", help="preset id or preset file")
ap.add_argument("--out", default="accuracy-map", help="output folder")
ap.add_argument("--points", type=int, default=41, help="grid points per axis")
ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE", help="as rangesim --set")
args = ap.parse_args()

# %% [markdown]
# Load the preset (inheritance and `set` as on the command line) and take its own grid ends from
# `show()`; the grid is log-spaced, so `numpy.geomspace` gives exactly the command line's grid.

# %%
sensor = rangesim.load(args.sensor, set=args.set)
params = sensor.show()["parameters"]


def preset_value(prefix):
    return next(v["value"] for k, v in params.items() if k.startswith(prefix))


signal = np.geomspace(preset_value("evaluation.signal_min_"), preset_value("evaluation.signal_max_"), args.points)
background = np.geomspace(preset_value("evaluation.background_min_"), preset_value("evaluation.background_max_"),
                          args.points)
result = sensor.evaluate(signal=signal, background=background)
s = result.summary
print(f"{sensor.id}: {s['points_detectable']} of {s['points_total']} grid points detectable; "
      f"signal range {s['signal_range_dB']:.1f} dB, background range {s['background_range_dB']:.1f} dB; "
      f"accuracy {1e3 * s['accuracy_min_m']:.3g} .. {1e3 * s['accuracy_max_m']:.3g} mm at {s['distance_m']:g} m")

# %% [markdown]
# `accuracy_m` is NaN where range cannot be derived; `detect` says why, as codes into `reasons`.

# %%
accuracy_mm = 1e3 * result.accuracy_m
for code, (reason, text) in enumerate(result.reasons):
    print(f"  {np.count_nonzero(result.detect == code):5d} points {reason}: {text}")

# %% [markdown]
# The map: accuracy in mm as colour (log scale) over log axes, the edge of the detectable area as a
# black contour.

# %%
os.makedirs(args.out, exist_ok=True)
try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    plt = None

if plt is None:
    path = os.path.join(args.out, "accuracy_map.npz")
    np.savez(path, signal=result.signal, background=result.background, accuracy_mm=accuracy_mm,
             detect=result.detect, reasons=np.array([r for r, _ in result.reasons]))
    print(f"matplotlib is not installed (Debian: python3-matplotlib): wrote the arrays to {path} instead "
          "(signal, background, accuracy_mm, detect, reasons)")
else:
    fig, ax = plt.subplots(figsize=(7, 5))
    from matplotlib.colors import LogNorm

    mesh = ax.pcolormesh(result.signal, result.background, accuracy_mm, shading="nearest", cmap="viridis",
                         norm=LogNorm())
    ax.contour(result.signal, result.background, result.detectable.astype(float), levels=[0.5], colors="black",
               linewidths=1)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(f"signal ({result.signal_unit})")
    ax.set_ylabel(f"background ({result.background_unit})")
    ax.set_title(f"{sensor.id}: rms range accuracy at {s['distance_m']:g} m")
    fig.colorbar(mesh, ax=ax, label="accuracy (mm)")
    path = os.path.join(args.out, "accuracy_map.png")
    fig.savefig(path, dpi=120, bbox_inches="tight")
    print(f"wrote {path}")
