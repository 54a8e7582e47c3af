"""Bad input raises rangesim.Error (a ValueError) with the command line's message, naming the key
(Error.key and the text); nothing is written anywhere."""
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

import rangesim
from rangesim_test_util import SCENES, cli_error, grid


class Errors(unittest.TestCase):
    def setUp(self):
        # Everything runs in an empty folder that must stay empty.
        self.tmp = tempfile.TemporaryDirectory()
        self.addCleanup(self.tmp.cleanup)
        self.cwd = os.getcwd()
        os.chdir(self.tmp.name)
        self.addCleanup(os.chdir, self.cwd)
        self.addCleanup(lambda: self.assertEqual(os.listdir(self.tmp.name), [], "something was written"))

    def error(self, call):
        with self.assertRaises(rangesim.Error) as c:
            call()
        self.assertIsInstance(c.exception, ValueError)
        return c.exception

    def same_as_cli(self, call, key, *cli_args):
        """The Python error carries the command's message for the same input, and the key."""
        e = self.error(call)
        self.assertEqual(str(e), cli_error(*cli_args))
        self.assertEqual(e.key, key)
        if key:  # the command's message names the flag (--max-trials) where Python has max_trials
            self.assertTrue(key in str(e) or key.replace("_", "-") in str(e), f"{key} not in: {e}")
        return e

    def test_preset_and_set(self):
        e = self.same_as_cli(lambda: rangesim.load("no-such-preset"), "preset", "show", "no-such-preset")
        self.assertIn("no-such-preset", str(e))
        self.same_as_cli(lambda: rangesim.load("ls-conventional", set={"multisampling.samplings": 65}),
                         "multisampling.samplings", "show", "ls-conventional", "--set", "multisampling.samplings=65")
        self.same_as_cli(lambda: rangesim.load("ls-conventional", set={"timing.clok_Hz": 1e6}), "timing.clok_Hz",
                         "show", "ls-conventional", "--set", "timing.clok_Hz=1000000.0")
        self.same_as_cli(lambda: rangesim.load("ls-conventional", set={"comparator.threshold_mode": "best"}),
                         "comparator.threshold_mode", "show", "ls-conventional", "--set",
                         "comparator.threshold_mode=best")
        # A cross-key check names both keys; Error.key is the first.
        e = self.same_as_cli(lambda: rangesim.load("ls-conventional", set={"pixel.columns": 1024}),
                             "timing.address_bits", "show", "ls-conventional", "--set", "pixel.columns=1024")
        self.assertIn("pixel.columns", str(e))
        self.same_as_cli(lambda: rangesim.load("tof-spad", set={"tdc.lsb_s": float("nan")}), "tdc.lsb_s", "show",
                         "tof-spad", "--set", "tdc.lsb_s=nan")

    def test_set_values_python_cannot_express_as_text(self):
        e = self.error(lambda: rangesim.load("tof-spad", set={"tdc.lsb_s": [1, 2]}))
        self.assertEqual(e.key, "tdc.lsb_s")
        self.assertIn("allowed", str(e))
        e = self.error(lambda: rangesim.load("tof-spad", set=42))
        self.assertEqual(e.key, "set")

    def test_evaluate_arguments(self):
        s = rangesim.load("ls-conventional")
        self.same_as_cli(lambda: s.evaluate(signal="0:1.5:5"), "signal", "evaluate", "ls-conventional", "--signal",
                         "0:1.5:5")
        self.same_as_cli(lambda: s.evaluate(signal=np.array([0.0, 0.5, 1.0])), "signal", "evaluate",
                         "ls-conventional", "--signal", "0:1:3")
        self.same_as_cli(lambda: s.evaluate(background=np.geomspace(1.0, 0.1, 4)), "background", "evaluate",
                         "ls-conventional", "--background", "1:0.1:4")
        # The command refuses --trials 1 as it parses the flag, in its own words; the module the
        # way the command's evaluate code does: both name the flag and its range.
        e = self.error(lambda: s.evaluate(trials=1))
        self.assertEqual(e.key, "trials")
        self.assertIn("--trials", str(e))
        self.assertIn("10000000", str(e))
        self.same_as_cli(lambda: s.evaluate(trials=5, max_trials=3), "max_trials", "evaluate", "ls-conventional",
                         "--trials", "5", "--max-trials", "3")
        self.same_as_cli(lambda: s.evaluate(samplings=99), "multisampling.samplings", "evaluate", "ls-conventional",
                         "--samplings", "99")
        self.same_as_cli(lambda: rangesim.load("tof-spad").evaluate(samplings=2), "samplings", "evaluate", "tof-spad",
                         "--samplings", "2")
        # Only the module takes arrays: one that is not ascending is refused naming the axis.
        e = self.error(lambda: s.evaluate(signal=np.array([0.01, 0.5, 0.2, 1.0])))
        self.assertEqual(e.key, "signal")
        self.assertIn("value [2] = 0.2 is not above the one before it", str(e))
        e = self.error(lambda: s.evaluate(signal=np.ones((2, 2))))
        self.assertEqual(e.key, "signal")

    def test_frame_rate_arguments(self):
        self.same_as_cli(lambda: rangesim.load("tof-spad").frame_rate(samplings=3), "samplings", "frame-rate",
                         "tof-spad", "--samplings", "3")

    def test_simulate_arguments(self):
        s = rangesim.load("tof-spad")
        scene = os.path.join(SCENES, "tof-spad-plane.toml")
        e = self.error(lambda: s.simulate(os.path.join(SCENES, "no-such-scene.toml")))
        self.assertEqual(str(e), cli_error("simulate", "tof-spad", "--scene",
                                           os.path.join(SCENES, "no-such-scene.toml"), "--kernel-only"))
        self.assertEqual(e.key, "scene")
        e = self.error(lambda: s.simulate(scene, frames=0))
        self.assertEqual(str(e), cli_error("simulate", "tof-spad", "--scene", scene, "--frames", "0", "--kernel-only"))
        self.assertIn("--frames", str(e))
        self.assertEqual(e.key, "frames")
        # A scene value out of its range: the key is the scene file's.
        with tempfile.TemporaryDirectory() as tmp:
            bad = os.path.join(tmp, "bad.toml")
            with open(bad, "w") as f:
                f.write('[target]\nshape = "plane"\ndistance_m = -1\n')
            e = self.error(lambda: s.simulate(bad))
            self.assertEqual(e.key, "target.distance_m")

        self.same_as_cli(lambda: s.simulate(scene, time_step=1e-9), "time_step", "simulate", "tof-spad", "--scene",
                         scene, "--time-step", "1e-9", "--kernel-only")
        lc = rangesim.load("ls-conventional")
        self.same_as_cli(lambda: lc.simulate(os.path.join(SCENES, "plane.toml"), no_aggregate=True), "no_aggregate",
                         "simulate", "ls-conventional", "--scene", os.path.join(SCENES, "plane.toml"),
                         "--no-aggregate", "--kernel-only")

    def test_systemc_once_per_process(self):
        # In a child process: the SystemC run equals the kernels' and a second one is refused.
        child = (
            "import os, sys, rangesim\n"
            "s = rangesim.load('tof-spad')\n"
            "scene = os.path.join(sys.argv[1], 'tof-spad-plane.toml')\n"
            "k, m = s.simulate(scene, seed=2), s.simulate(scene, seed=2, systemc=True)\n"
            "assert m.summary['harness'] == 'systemc' and k.summary['harness'] == 'kernel'\n"
            "assert m.points_csv == k.points_csv and m.frames_csv == k.frames_csv\n"
            "assert m.summary['cycles'] == k.summary['cycles']\n"
            "try:\n"
            "    s.simulate(scene, systemc=True)\n"
            "except rangesim.Error as e:\n"
            "    print('refused', e.key, e)\n")
        p = subprocess.run([sys.executable, "-B", "-c", child, SCENES], capture_output=True, text=True)
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertIn("refused systemc systemc=True: SystemC elaborates once per process", p.stdout)

    def test_kernel_arguments(self):
        lc = rangesim.load("ls-conventional")
        e = self.error(lambda: lc.kernel("tdc"))
        self.assertEqual(e.key, "block")
        self.assertIn("tof-spad", str(e))
        self.assertIn("address_search", str(e))
        search = lc.kernel("address_search")
        e = self.error(lambda: search.tick(start=True, act=[True] * 10))
        self.assertEqual(e.key, "act")
        self.assertIn(str(search.columns), str(e))
        tdc = rangesim.load("tof-spad").kernel("tdc")
        for call, key in ((lambda: tdc.hit(0, -1, 0), "cycle"), (lambda: tdc.hit(tdc.columns, 0, 0), "who"),
                          (lambda: tdc.hit(0, 0, tdc.phase_bins), "bin")):
            e = self.error(call)
            self.assertEqual(e.key, key)
            self.assertIn(key, str(e))
        gate = rangesim.load("tof-lockin").kernel("lockin_gate_generator")
        gate.start()
        e = self.error(lambda: gate.advance(gate.cycles_to_edge() + 1))
        self.assertEqual(e.key, "n")

    def test_monte_carlo_grid_from_the_preset_is_checked_before_running(self):
        # A Monte Carlo call with a bad later argument fails before any evaluation runs.
        s = rangesim.load("tof-spad")
        sig, bg, _, _ = grid(s, 3, 2)
        e = self.error(lambda: s.evaluate(signal=sig, background=bg, trials=10, threads=0))
        self.assertEqual(e.key, "threads")


if __name__ == "__main__":
    unittest.main()
