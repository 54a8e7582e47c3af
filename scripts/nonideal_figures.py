#!/usr/bin/env python3
"""Figures of the non-idealities (docs/model-limits.md), made with rangesim's own commands.

(a) step-scene range profiles with the point spread off and on: tof-lockin along a row across its
    column step (flying pixels), ls-demodulation down a beam position across its row step (mixed rows);
    ls-conventional likewise down a beam position across the row step (a row that sees both stripes);
(b) accuracy against frames averaged, tof-lockin at one operating point: golden and the clock-level
    Monte Carlo (evaluate --trials; every trial a pixel of another chip), the chip's fixed pattern
    (1 % tap gain mismatch) on and off.

Usage: /usr/bin/python3 scripts/nonideal_figures.py [--rangesim build/app/rangesim] [--out docs/nonideal]
       [--figures step,lsc-step,floor]
Writes PNGs and the numbers behind them (CSV) into --out; the rangesim runs go to --work.
"""
import argparse
import csv
import json
import math
import os
import subprocess

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BLUR_ON = ["--set", "blur.psf=gaussian", "--set", "blur.gaussian_sigma_px=1.0"]
BLUR_OFF = ["--set", "blur.psf=none"]


def run(cmd):
    print("$ " + " ".join(cmd), flush=True)
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)


def range_map(folder):
    with open(os.path.join(folder, "range_map.csv")) as f:
        rows = list(csv.reader(f))
    return [[float(v) if v else math.nan for v in r[1:]] for r in rows[1:]]


def simulate(rs, sensor, scene, extra, out):
    run([rs, "simulate", sensor, "--scene", os.path.join(ROOT, "scenes", scene), "--out", out, "--force", "--no-plots"]
        + extra)
    return range_map(out)


def plot_blur_pair(ax, maps, xs, value_at, sensor, where, title, xlabel):
    # Point spread off ("sharp") and on ("blur") along xs; returns the CSV lines (sensor, blur, row,
    # column or beam position, range) with `where(x)` giving the middle two.
    lines = []
    for name, style in (("sharp", "o-"), ("blur", "s--")):
        vals = [value_at(maps[name], x) for x in xs]
        ax.plot(xs, vals, style, label="blur.psf = none" if name == "sharp" else "gaussian, sigma 1 px")
        lines += [(sensor, name) + where(x) + (v,) for x, v in zip(xs, vals)]
    ax.set(title=title, xlabel=xlabel, ylabel="range (m)")
    ax.legend()
    return lines


def save_profile(fig, out, stem, header, lines):
    fig.tight_layout()
    fig.savefig(os.path.join(out, stem + ".png"), dpi=110)
    with open(os.path.join(out, stem + ".csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(lines)


def blur_pair(rs, sensor, scene, work, prefix, extra=()):
    return {name: simulate(rs, sensor, scene, blur + list(extra), os.path.join(work, prefix + name))
            for name, blur in (("sharp", BLUR_OFF), ("blur", BLUR_ON))}


def step_profiles(rs, work, out):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    # tof-lockin: the middle row across the column step (near 2 m | far 9 m at column 134.4).
    lk = blur_pair(rs, "tof-lockin", "tof-lockin-step.toml", work, "lockin_")
    row = len(lk["sharp"]) // 2
    lines = plot_blur_pair(axes[0], lk, list(range(124, 146)), lambda m, c: m[row][c], "tof-lockin",
                           lambda c: (row, c), "tof-lockin, step 2 m | 9 m, row %d" % row, "column")
    # ls-demodulation: one beam position down the rows across the row step (0.9 m | 1.2 m).
    dm = blur_pair(rs, "ls-demodulation", "step.toml", work, "demod_")
    nrows = len(dm["sharp"])
    b = max(range(len(dm["sharp"][0])), key=lambda j: sum(not math.isnan(dm["sharp"][r][j]) for r in range(nrows)))
    lines += plot_blur_pair(axes[1], dm, list(range(nrows // 2 - 10, nrows // 2 + 10)), lambda m, r: m[r][b],
                            "ls-demodulation", lambda r: (r, b),
                            "ls-demodulation, step 0.9 m | 1.2 m, beam position %d" % b, "row")
    save_profile(fig, out, "step_profile_blur", ["sensor", "blur", "row", "column_or_beam_position", "range_m"],
                 lines)


def lsc_step_profile(rs, work, out):
    # ls-conventional: one beam position down the rows across the row step (0.9 m | 1.2 m); with the
    # point spread a row near the step sees the stripes of both depths (two spot profiles).
    ls = blur_pair(rs, "ls-conventional", "step.toml", work, "lsc_", ["--csv"])
    nrows, npos = len(ls["sharp"]), len(ls["sharp"][0])
    # The middle beam position (a stripe near an array edge is spread against the edge's clamp).
    b = npos // 2
    fig, ax = plt.subplots(figsize=(6, 4))
    lines = plot_blur_pair(ax, ls, list(range(nrows // 2 - 8, nrows // 2 + 9)), lambda m, r: m[r][b],
                           "ls-conventional", lambda r: (r, b),
                           "ls-conventional, step 0.9 m | 1.2 m, beam position %d" % b, "row")
    save_profile(fig, out, "lsc_step_profile_blur", ["sensor", "blur", "row", "beam_position", "range_m"], lines)


def frames_floor(rs, work, out, trials):
    frames = [1, 3, 10, 30, 100, 300, 1000]
    cases = (("fixed pattern on (tap mismatch 1 %)", ["--set", "fixed_pattern.tap_mismatch_fraction=0.01"]),
             ("fixed pattern off", ["--set", "fixed_pattern.tap_mismatch_fraction=0"]))
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    rows = []
    for label, extra in cases:
        g, mc, lo, hi = [], [], [], []
        for n in frames:
            folder = os.path.join(work, "frames_%s_%d" % ("on" if "on" in label else "off", n))
            run([rs, "evaluate", "tof-lockin", "--signal", "3e-10:3e-10:1", "--background", "1e-11:1e-11:1",
                 "--frames", str(n), "--trials", str(trials), "--no-plots", "--force", "--out", folder] + extra)
            with open(os.path.join(folder, "mc_points.csv")) as f:
                p = next(csv.DictReader(f))
            g.append(float(p["golden_accuracy_m"]) * 1e3)
            mc.append(float(p["accuracy_m"]) * 1e3)
            lo.append(float(p["accuracy_lo_m"]) * 1e3)
            hi.append(float(p["accuracy_hi_m"]) * 1e3)
            rows.append([label, n, g[-1], mc[-1], lo[-1], hi[-1]])
        line, = ax.plot(frames, g, "-", label="golden, " + label)
        ax.errorbar(frames, mc, yerr=[[m - l for m, l in zip(mc, lo)], [h - m for m, h in zip(mc, hi)]], fmt="o",
                    color=line.get_color(), label="Monte Carlo 95 % CI, " + label)
    ax.plot(frames, [rows[len(frames)][2] / math.sqrt(n) for n in frames], ":", color="grey", label="1/sqrt(N)")
    ax.set(xscale="log", yscale="log", xlabel="frames averaged N", ylabel="range accuracy (mm)",
           title="tof-lockin, 0.3 nA signal, 10 pA background, 1 m")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "accuracy_vs_frames_floor.png"), dpi=110)
    with open(os.path.join(out, "accuracy_vs_frames_floor.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case", "frames", "golden_mm", "mc_mm", "mc_lo_mm", "mc_hi_mm"])
        w.writerows(rows)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rangesim", default=os.path.join(ROOT, "build", "app", "rangesim"))
    ap.add_argument("--out", default=os.path.join(ROOT, "docs", "nonideal"))
    ap.add_argument("--work", default="/tmp/rangesim-nonideal")
    ap.add_argument("--trials", type=int, default=400)
    ap.add_argument("--figures", default="step,lsc-step,floor",
                    help="comma-separated: step (tof-lockin, ls-demodulation), lsc-step (ls-conventional), floor")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    os.makedirs(a.work, exist_ok=True)
    which = a.figures.split(",")
    if "step" in which:
        step_profiles(a.rangesim, a.work, a.out)
    if "lsc-step" in which:
        lsc_step_profile(a.rangesim, a.work, a.out)
    if "floor" in which:
        frames_floor(a.rangesim, a.work, a.out, a.trials)


if __name__ == "__main__":
    main()
