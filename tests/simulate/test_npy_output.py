"""simulate's .npy outputs (app/simulate/npy_writer.h) as numpy.load reads them equal the CSV of
the same run: every range and every points field, NaN where the CSV cell is empty, the CSV text
being the .npy value printed with "%.9g". Exit 77 (skipped) without NumPy."""
import csv
import os
import subprocess
import sys
import tempfile

try:
    import numpy as np
except ImportError:
    print("NumPy not found (Debian: python3-numpy): skipped")
    sys.exit(77)

BIN = os.environ["RANGESIM_BIN"]
SCENES = os.environ["RANGESIM_SCENE_DIR"]


def run(sensor, scene, frames, fmt, out):
    args = [BIN, "simulate", sensor, "--scene", os.path.join(SCENES, scene), "--kernel-only", "--no-plots",
            "--points", "--json", "--out", out, fmt]
    if frames:
        args += ["--frames", str(frames)]
    p = subprocess.run(args, capture_output=True, text=True)
    assert p.returncode == 0, p.stderr


def text(v):
    return "" if not np.isfinite(v) else "%.9g" % v


def check_exact_size(path, arr):
    """The file is its header and the array's bytes, nothing more: numpy.load would not notice
    bytes after the array (the writer reserves the file's blocks before writing, app/simulate/npy_writer.cpp)."""
    with open(path, "rb") as f:
        major, _ = np.lib.format.read_magic(f)
        if major == 1:
            np.lib.format.read_array_header_1_0(f)
        else:
            np.lib.format.read_array_header_2_0(f)
        start = f.tell()
    size = os.path.getsize(path)
    assert size == start + arr.nbytes, f"{path}: {size} bytes, header {start} + array {arr.nbytes}"


def check_equal(csv_rows, got, what):
    assert len(csv_rows) == len(got), f"{what}: {len(csv_rows)} CSV lines, {len(got)} .npy rows"
    for i, (a, b) in enumerate(zip(csv_rows, got)):
        assert a == b, f"{what} row {i}: CSV {a}\n.npy {b}"


def main():
    nan_cells = 0
    cases = [("ls-conventional", "plane.toml", 12), ("ls-conventional", "step.toml", 12),
             ("tof-spad", "tof-spad-plane.toml", 1),
             ("tof-lockin", "tof-lockin-plane.toml", 0)]
    with tempfile.TemporaryDirectory() as tmp:
        for sensor, scene, frames in cases:
            a, b = os.path.join(tmp, scene + "-npy"), os.path.join(tmp, scene + "-csv")
            run(sensor, scene, frames, "--npy", a)
            run(sensor, scene, frames, "--csv", b)
            assert not os.path.exists(os.path.join(a, "range_map.csv")), "--npy wrote range_map.csv"
            assert not os.path.exists(os.path.join(b, "range_map.npy")), "--csv wrote range_map.npy"
            with open(os.path.join(b, "range_map.csv")) as f:
                rows = list(csv.reader(f))
            m = np.load(os.path.join(a, "range_map.npy"))
            assert m.dtype == np.float64 and m.ndim == 2, f"{sensor}: range_map.npy {m.dtype} {m.shape}"
            assert m.shape == (len(rows) - 1, len(rows[0]) - 1), f"{sensor}: shape {m.shape}"
            assert np.isfinite(m).any(), f"{sensor}: the map has no range"
            check_exact_size(os.path.join(a, "range_map.npy"), m)
            nan_cells += int(np.isnan(m).sum())
            check_equal([r[1:] for r in rows[1:]], [[text(v) for v in line] for line in m], sensor + " range_map")
            points_csv = os.path.join(b, "points.csv")
            if not os.path.exists(points_csv):
                assert not os.path.exists(os.path.join(a, "points.npy")), f"{sensor}: points.npy without points.csv"
                print(f"{sensor}: range_map.npy {m.shape} equals range_map.csv")
                continue
            with open(points_csv) as f:
                prow = list(csv.reader(f))
            p = np.load(os.path.join(a, "points.npy"))
            check_exact_size(os.path.join(a, "points.npy"), p)
            assert list(p.dtype.names) == prow[0], f"{sensor}: fields {p.dtype.names} against {prow[0]}"
            ints = [n for n in p.dtype.names if p.dtype[n].kind in "ib"]
            assert p.dtype["frame"] == np.int32 and p.dtype["row"] == np.int32, f"{sensor}: index fields {p.dtype}"
            assert p.dtype["valid"] == np.bool_ and p.dtype["detected"] == np.bool_, f"{sensor}: flag fields {p.dtype}"
            got = [[str(int(x[n])) if n in ints else text(float(x[n])) for n in p.dtype.names] for x in p]
            check_equal(prow[1:], got, sensor + " points")
            nan_cells += sum(int(np.isnan(p[n]).sum()) for n in p.dtype.names if n not in ints)
            print(f"{sensor}: range_map.npy {m.shape} and points.npy ({len(p)} records) equal the CSV")
    assert nan_cells > 0, "no empty cell anywhere: NaN <-> empty was not exercised"
    print(f"{nan_cells} empty cells (NaN) compared")
    return 0


if __name__ == "__main__":
    sys.exit(main())
