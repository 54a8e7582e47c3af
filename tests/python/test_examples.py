"""The example scripts of examples/python run: the testbench passes, and each of its faults is
caught; the accuracy map is drawn with matplotlib and written as arrays without it; the overhead
benchmark (python/bench) runs."""
import json
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

from rangesim_test_util import SOURCE

EXAMPLES = os.path.join(SOURCE, "examples", "python")


def run(script, *args, hide_matplotlib=False):
    cmd = [sys.executable, "-B"]
    if hide_matplotlib:  # as on a machine without it: the import fails
        cmd += ["-c", "import runpy, sys; sys.modules['matplotlib'] = None; sys.argv = sys.argv[1:]; "
                      "runpy.run_path(sys.argv[0], run_name='__main__')"]
    p = subprocess.run(cmd + [os.path.join(EXAMPLES, script), *args], capture_output=True, text=True)
    return p.returncode, p.stdout + p.stderr


def have_matplotlib():
    try:
        import matplotlib  # noqa: F401
        return True
    except ImportError:
        return False


class Examples(unittest.TestCase):
    def test_testbench_passes(self):
        rc, out = run("testbench.py", "--operations", "200")
        self.assertEqual(rc, 0, out)
        self.assertIn("200 transactions", out)
        self.assertIn("0 mismatch(es)", out)
        self.assertIn("transaction 0: {'found'", out)

    def test_testbench_catches_each_fault(self):
        for fault in ("addr-bit", "model-edges"):
            with self.subTest(fault=fault):
                rc, out = run("testbench.py", "--operations", "200", "--inject-fault", fault)
                self.assertEqual(rc, 1, out)
                self.assertIn("MISMATCH operation", out)

    def test_testbench_on_a_variant(self):
        rc, out = run("testbench.py", "--operations", "50", "--set", "pixel.columns=64", "--set",
                      "timing.address_bits=6")
        self.assertEqual(rc, 0, out)
        self.assertIn("64 columns, 6 address bits", out)

    def test_accuracy_map(self):
        with tempfile.TemporaryDirectory() as out_dir:
            rc, out = run("accuracy_map.py", "tof-spad", "--points", "15", "--out", out_dir)
            self.assertEqual(rc, 0, out)
            self.assertIn("grid points detectable", out)
            expected = "accuracy_map.png" if have_matplotlib() else "accuracy_map.npz"
            self.assertEqual(os.listdir(out_dir), [expected])

    def test_accuracy_map_without_matplotlib(self):
        with tempfile.TemporaryDirectory() as out_dir:
            rc, out = run("accuracy_map.py", "ls-conventional", "--points", "9", "--out", out_dir,
                          hide_matplotlib=True)
            self.assertEqual(rc, 0, out)
            self.assertIn("matplotlib is not installed", out)
            arrays = np.load(os.path.join(out_dir, "accuracy_map.npz"))
            self.assertEqual(arrays["accuracy_mm"].shape, (9, 9))
            self.assertEqual(str(arrays["reasons"][0]), "detectable")
            self.assertTrue(np.any(np.isfinite(arrays["accuracy_mm"])))

    def test_kernel_step_bench_runs(self):
        # The overhead benchmark of docs/python.md, tiny: every step has both its numbers.
        script = os.path.join(SOURCE, "python", "bench", "kernel_step_bench.py")
        p = subprocess.run([sys.executable, "-B", script, "--steps", "2000", "--cpp-steps", "20000", "--json"],
                           capture_output=True, text=True)
        self.assertEqual(p.returncode, 0, p.stderr)
        rows = json.loads(p.stdout)["rows"]
        self.assertEqual(len(rows), 6)
        for r in rows:
            self.assertGreater(r["cpp_ns"], 0, r)
            self.assertGreater(r["python_ns"], 0, r)


if __name__ == "__main__":
    unittest.main()
