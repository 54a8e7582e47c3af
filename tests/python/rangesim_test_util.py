"""What the Python tests share: the built command, the source tree, running the command, and the
grid a preset evaluates by default (its own ends, fewer points)."""
import json
import os
import subprocess
import tempfile

import numpy as np

import rangesim

BIN = os.environ["RANGESIM_BIN"]  # the built `rangesim` (set by tests/python/CMakeLists.txt)
SOURCE = os.environ["RANGESIM_SOURCE_DIR"]
SCENES = os.path.join(SOURCE, "scenes")
ERROR_PREFIX = "rangesim: error: "


def run_cli(*args, cwd=None):
    """(exit code, stdout, stderr) of the command."""
    p = subprocess.run([BIN, *args], capture_output=True, text=True, cwd=cwd)
    return p.returncode, p.stdout, p.stderr


def cli_json(*args):
    rc, out, err = run_cli(*args)
    if rc != 0:
        raise AssertionError(f"rangesim {' '.join(args)}: exit {rc}\n{err}")
    return json.loads(out)


def cli_error(*args):
    """The message the command prints for bad input (exit 2), without its prefix, run in an empty
    folder that must stay empty."""
    with tempfile.TemporaryDirectory() as cwd:
        rc, _, err = run_cli(*args, cwd=cwd)
        if rc != 2:
            raise AssertionError(f"rangesim {' '.join(args)}: exit {rc}, expected 2\n{err}")
        if os.listdir(cwd):
            raise AssertionError(f"rangesim {' '.join(args)} wrote {os.listdir(cwd)}")
    line = err.strip().splitlines()[-1]
    assert line.startswith(ERROR_PREFIX), err
    return line[len(ERROR_PREFIX):]


def preset_value(sensor, prefix):
    """The value of the first parameter whose key starts with `prefix` (units differ by sensor)."""
    params = sensor.show()["parameters"]
    return next(v["value"] for k, v in params.items() if k.startswith(prefix))


def grid(sensor, n_signal, n_background):
    """The preset's own grid ends with fewer points: as arrays and as the command's LO:HI:N."""
    s_lo, s_hi = preset_value(sensor, "evaluation.signal_min_"), preset_value(sensor, "evaluation.signal_max_")
    b_lo, b_hi = preset_value(sensor, "evaluation.background_min_"), preset_value(sensor, "evaluation.background_max_")
    return (np.geomspace(s_lo, s_hi, n_signal), np.geomspace(b_lo, b_hi, n_background),
            f"{s_lo!r}:{s_hi!r}:{n_signal}", f"{b_lo!r}:{b_hi!r}:{n_background}")


def sensors():
    return [rangesim.load(p["id"]) for p in rangesim.presets() if p["golden_modelled"]]


def g6(v):
    """A number as the command writes it in CSV ({:.6g}, empty when not finite)."""
    return "" if not np.isfinite(v) else f"{v:.6g}"


def g9(v):
    return "" if not np.isfinite(v) else f"{v:.9g}"


def read_csv(path):
    with open(path) as f:
        return [line.rstrip("\n").split(",") for line in f]
