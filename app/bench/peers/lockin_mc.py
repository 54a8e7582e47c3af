#!/usr/bin/python3
"""NumPy peer of `rangesim evaluate tof-lockin --trials N` at one operating point: the same physics
(systemc/tof_lockin: Poisson tap charges of the frame's total mean, the offset charge's own Poisson
draw, kTC and read noise, FD
saturation, column ADC, ambient frame subtracted per tap, range c T0 / 2 x b / (a + b), frames
averaged), vectorised over the trials as a scientist would write it. `rangesim bench` runs it
beside rangesim at the same point and compares the rms range errors (docs/bench.md).

Reads the preset TOML itself (tomllib). Prints one JSON line: trials, detected, rms_error_m,
bias_m, std_m, cpu_s (this process's CPU time, start-up included)."""
import argparse
import json
import math
import sys
import time
import tomllib

import numpy as np

Q = 1.602176634e-19  # C
KB = 1.380649e-23  # J/K
C_LIGHT = 299792458.0  # m/s


def preset_values(path):
    with open(path, "rb") as f:
        doc = tomllib.load(f)
    if "inherits" in doc.get("sensor", {}):
        sys.exit("lockin_mc.py: presets with 'inherits' are not supported")
    return {sec: {k: (v["value"] if isinstance(v, dict) else v) for k, v in tab.items()} for sec, tab in doc.items()}


def overlap(a0, a1, b0, b1):
    return max(0.0, min(a1, b1) - max(a0, b0))


def tap_means(p, signal_A, background_A, delay_s, led_on):
    """Mean electrons on FD1 and FD2 over one frame of N_acc periods (rectangular pulse)."""
    src, px, gates = p["source"], p["pixel"], p["gates"]
    T0 = src["pulse_width_s"]
    fg = gates["clock_Hz"]
    t0_cycles = round(T0 * fg)
    period_cycles = round(T0 / src["duty_cycle"] * fg)
    Trep = period_cycles / fg
    n = gates["accumulations_per_frame"]
    eta = px["charge_separation"]
    windows = [(0, t0_cycles), (t0_cycles, 2 * t0_cycles), (2 * t0_cycles, period_cycles)]
    g = []
    for a_c, b_c in windows:
        a, b = a_c / fg, b_c / fg
        e = background_A * n * (b - a)
        if led_on and signal_A != 0:
            # Pulse of period k lands at delay + k Trep: its own period's window (n times) and the
            # following periods' (n - lag times) while its tail reaches them.
            light, lag = 0.0, 0
            while lag < n:
                o = overlap(delay_s - lag * Trep, delay_s + T0 - lag * Trep, a, b)
                if o == 0 and delay_s + T0 - lag * Trep < a:
                    break
                light += (n - lag) * o
                lag += 1
            e += eta * signal_A * light + (1 - eta) * signal_A * T0 / Trep * n * (b - a)
        g.append(e / Q)
    leak = (1 - px["drain_efficiency"]) / 2
    # The preset's dark current is at dark.reference_temperature_K; it doubles every doubling_temperature_K.
    d = p.get("dark", {})
    law = 2.0 ** ((p["noise"]["temperature_K"] - d["reference_temperature_K"]) / d["doubling_temperature_K"]) if d else 1.0
    dark = n * p["noise"]["dark_current_A"] * law * Trep / Q
    return np.array([g[0] + leak * g[2] + dark, g[1] + leak * g[2] + dark])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--preset", required=True)
    ap.add_argument("--signal", type=float, required=True)
    ap.add_argument("--background", type=float, required=True)
    ap.add_argument("--trials", type=int, required=True)
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    p = preset_values(a.preset)
    if p["source"].get("rise_time_s", 0.0) != 0.0:
        sys.exit("lockin_mc.py: only the rectangular pulse (rise_time_s = 0) is implemented")
    px, rd, nz, ev = p["pixel"], p["readout"], p["noise"], p["evaluation"]
    distance = ev["distance_m"]
    delay = 2 * distance / C_LIGHT
    A = px["source_follower_gain"]
    C = np.array([px["fd1_capacitance_F"], px["fd2_capacitance_F"]])
    ktc = np.zeros(2) if rd["cds_enabled"] else np.sqrt(KB * nz["temperature_K"] / C)  # at the FD
    lsb = rd["adc_full_scale_V"] / 2.0 ** rd["adc_bits"]
    top = 2 ** rd["adc_bits"] - 1
    ambient = rd["ambient_subtraction"]
    maps = max(1, ev.get("frames_averaged", 1))
    rng = np.random.default_rng(a.seed)
    means = {on: tap_means(p, a.signal, a.background, delay, on) for on in (True, False)}

    # The offset charge C V_offset / q of each FD is Poisson too (offset_charge.shot_noise).
    n_off = px["offset_voltage_V"] * C / Q if p.get("offset_charge", {}).get("shot_noise", False) else np.zeros(2)

    def frame_codes(on, T):
        N = rng.poisson(means[on], size=(T, 2)) + (rng.poisson(n_off, size=(T, 2)) - n_off)
        z = rng.standard_normal((T, 4))
        swing = np.minimum(N * (Q / C) + px["offset_voltage_V"] + z[:, :2] * ktc, px["saturation_voltage_V"])
        v = A * swing + z[:, 2:] * nz["read_noise_V"]
        return np.clip(np.floor(v / lsb), 0, top)

    T = a.trials
    total = np.zeros(T)
    ok = np.ones(T, dtype=bool)
    for _ in range(maps):
        led = frame_codes(True, T)
        tap = led * lsb - rd["offset_calibration_V"]
        if ambient:
            tap -= frame_codes(False, T) * lsb
        s = tap[:, 0] + tap[:, 1]
        good = (led[:, 0] != top) & (led[:, 1] != top) & (s > 0) & (s >= rd["detection_threshold_V"] * (1 - 1e-9))
        with np.errstate(divide="ignore", invalid="ignore"):
            total += C_LIGHT * p["source"]["pulse_width_s"] / 2 * tap[:, 1] / s
        ok &= good
    err = total[ok] / maps - distance
    print(json.dumps({"trials": T, "detected": int(ok.sum()),
                      "rms_error_m": float(np.sqrt(np.mean(err ** 2))) if err.size else None,
                      "bias_m": float(err.mean()) if err.size else None,
                      "std_m": float(err.std(ddof=1)) if err.size > 1 else None,
                      "cpu_s": time.process_time()}))


if __name__ == "__main__":
    main()
