#!/usr/bin/python3
"""NumPy peer of `rangesim simulate ls-conventional --scene scenes/plane.toml --kernel-only`: the
full range map (one frame access per beam position) with the same physics as
systemc/ls_conventional (scene radiometry and triangulation of scene_optics.cpp, Gaussian spot,
Poisson photo/background/dark electrons drawn per sampling interval, kTC and read noise frozen for
the frame access, saturation, tracking comparator threshold, latched activations, leftmost and
rightmost activated column per sampling, centre sum / 2n rounded to Q.8, triangulated range),
vectorised over every (beam position, row) at once as a scientist would write it. Only the pixels
near the stripe are drawn: one whose mean signal swing is below half the comparator's margin
above the background sits more than 10 noise sigmas below the threshold.

Plane targets only. Reads the preset and the scene TOML itself (tomllib). Writes the range map
(--out FILE.npy, rows x beam positions, NaN = no range) and prints one JSON line: points_visible,
points_detected, rms_error_m, cpu_s (this process's CPU time, start-up included)."""
import argparse
import json
import math
import sys
import time
import tomllib

import numpy as np

Q = 1.602176634e-19  # C
KB = 1.380649e-23  # J/K


def values(path):
    with open(path, "rb") as f:
        doc = tomllib.load(f)
    return {sec: {k: (v["value"] if isinstance(v, dict) and "value" in v else v) for k, v in tab.items()}
            for sec, tab in doc.items() if isinstance(tab, dict)}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--preset", required=True)
    ap.add_argument("--scene", required=True)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--out", default="")
    a = ap.parse_args()
    p, s = values(a.preset), values(a.scene)
    if "inherits" in p.get("sensor", {}):
        sys.exit("ls_conventional_map.py: presets with 'inherits' are not supported")
    if s["target"].get("shape", "plane") != "plane":
        sys.exit("ls_conventional_map.py: plane targets only")
    px, spot, cmp, opt, tm = p["pixel"], p["spot"], p["comparator"], p["optics"], p["timing"]
    if cmp["adc_bits"] != 1:
        sys.exit("ls_conventional_map.py: 1-bit comparators only")
    R, C, B, N = px["rows"], px["columns"], tm["beam_positions"], p["multisampling"]["samplings"]
    f, d, pitch = opt["focal_length_m"], opt["baseline_m"], px["pitch_m"]
    cam = s.get("camera", {})
    fnum = cam.get("f_number", opt["f_number"])
    ff = cam.get("fill_factor", px["fill_factor"])
    resp = cam.get("responsivity_A_per_W", px["responsivity_A_per_W"])
    T, Cpd, A = px["integration_time_s"], px["pd_capacitance_F"], px["source_follower_gain"]
    sigma_px = spot["sigma_per_fwhm"] * spot["fwhm_px"]
    rho, z = s["target"]["reflectance"], s["target"]["distance_m"]
    beam = s["beam"]
    # Radiometry (scene_optics.cpp): peak signal swing of the stripe and background swing.
    lens_area = math.pi * (f / (2 * fnum)) ** 2
    collected = rho * (beam["power_W"] / R) * lens_area / math.pi
    signal_V = resp * ff * collected / (sigma_px * math.sqrt(2 * math.pi)) * T / Cpd / z ** 2
    bg_V = resp * ff * pitch ** 2 * rho * s["background"]["irradiance_W_per_m2"] / (4 * fnum ** 2) * T / Cpd
    dark_V = px["dark_current_A"] * T / Cpd
    e_per_V = Cpd / Q
    if cmp["threshold_mode"] == "tracking":
        thr = A * (bg_V + dark_V) + cmp["threshold_above_background_V"]
    else:
        thr = cmp["fixed_threshold_V"]
    # Beam positions and the stripe's column on every row (a plane: the same on every row).
    cx = 0.5 * (C - 1)
    b = np.arange(B)
    u = b * C / B + beam.get("column_offset_px", 0.0)
    cot = (f * d / beam["reference_distance_m"] - (u - cx) * pitch) / f
    x0 = (f * d / z - f * cot) / pitch + cx  # (B,)
    visible = (x0 >= 0) & (x0 <= C - 1)
    # Pixels near the stripe: mean signal swing >= half the margin above the background.
    margin = thr / A - bg_V - dark_V
    h = sigma_px * math.sqrt(2 * math.log(signal_V / (0.5 * margin))) if signal_V > 0.5 * margin else -1
    W = int(math.ceil(h)) + 1
    rng = np.random.default_rng(a.seed)
    cols = np.floor(x0)[:, None, None] + np.arange(-W, W + 2)[None, None, :]  # (B, 1, P)
    cols = np.broadcast_to(cols, (B, R, cols.shape[2]))
    inside = (cols >= 0) & (cols <= C - 1)
    g = np.exp(-((cols - x0[:, None, None]) ** 2) / (2 * sigma_px ** 2))
    mean_step_e = (signal_V * g + bg_V + dark_V) * e_per_V / N  # electrons per sampling interval
    electrons = np.cumsum(rng.poisson(mean_step_e[..., None], size=mean_step_e.shape + (N,)), axis=-1)
    ktc = rng.standard_normal(mean_step_e.shape) * math.sqrt(KB * px["temperature_K"] / Cpd)
    read = rng.standard_normal(mean_step_e.shape) * px["read_noise_V"]
    v = np.minimum(electrons / e_per_V + ktc[..., None], px["saturation_voltage_V"]) + read[..., None]
    act = np.logical_or.accumulate((A * v >= thr) & inside[..., None], axis=-1)  # latched, (B, R, P, N)
    c4 = cols[..., None]
    left = np.where(act, c4, C).min(axis=2)  # (B, R, N)
    right = np.where(act, c4, -1).max(axis=2)
    found = right >= 0
    total = np.where(found, left + right, 0).sum(axis=-1)
    n = found.sum(axis=-1)
    valid = n > 0
    with np.errstate(divide="ignore", invalid="ignore"):
        centre = np.floor((total * 256 + n) / (2 * n)) / 256
        rng_m = d * f / ((centre - cx) * pitch + f * cot[:, None])
    rng_m = np.where(valid, rng_m, np.nan)
    det = valid & visible[:, None]
    err = rng_m[det] - z
    if a.out:
        np.save(a.out, rng_m.T)
    print(json.dumps({"points_visible": int(visible.sum()) * R, "points_detected": int(det.sum()),
                      "rms_error_m": float(np.sqrt(np.mean(err ** 2))) if err.size else None,
                      "window_px": 2 * W + 2, "cpu_s": time.process_time()}))


if __name__ == "__main__":
    main()
