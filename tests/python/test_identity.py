"""The Python module against the command line: for the same inputs, on every registered sensor,
the same JSON (list, show, frame-rate, table, evaluate's summary.json with and without Monte
Carlo, simulate's summary.json) and arrays that print as the command's CSV files."""
import json
import os
import tempfile
import unittest

import numpy as np

import rangesim
from rangesim_test_util import SCENES, cli_json, g6, g9, grid, read_csv, run_cli, sensors

# Summary keys that time the run itself (wall clock), different in every run of anything, and how the
# command's --json says its files went out (the module writes none).
WALL_CLOCK_KEYS = {"wall_time_s", "simulation_wall_time_s", "simulated_cycles_per_s", "photons_per_s",
                   "output_wall_time_s", "output_cpu_s", "output_cpu_during_run_s", "output_begun_during_run"}


class CommandCase(unittest.TestCase):
    """A scratch folder for the command's output files."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.addCleanup(self.tmp.cleanup)

    def out(self, name):
        return os.path.join(self.tmp.name, name)


class Identity(CommandCase):
    """list, show, frame-rate and evaluate (golden)."""

    def test_presets_is_list_json(self):
        # The module does not co-simulate RTL: its command table has no "cosim"; the rest is the same.
        cli = cli_json("list", "--json")
        for s in cli:
            del s["commands"]["cosim"]
        self.assertEqual(rangesim.presets(), cli)
        self.assertGreaterEqual(len(rangesim.presets()), 4)

    def test_show_with_set_is_show_json(self):
        for s in sensors():
            key = next(k for k in s.show()["parameters"] if k.startswith("evaluation.signal_points"))
            with self.subTest(sensor=s.id):
                py = rangesim.load(s.id, set={key: 7}).show()
                self.assertEqual(py, cli_json("show", s.id, "--set", f"{key}=7", "--json"))
                self.assertEqual(py["parameters"][key]["value"], 7)
                self.assertEqual(py["parameters"][key]["source"], "command line --set")

    def test_preset_file_with_base_and_set(self):
        path = self.out("variant.toml")
        with open(path, "w") as f:
            f.write('base = "tof-spad"\n[tdc]\nlsb_s = { value = 100e-12, source = "what-if" }\n')
        py = rangesim.load(path, set=["laser.repetition_rate_Hz=2e6"]).show()
        self.assertEqual(py, cli_json("show", path, "--set", "laser.repetition_rate_Hz=2e6", "--json"))
        self.assertEqual(py["parameters"]["tdc.lsb_s"]["source"], "what-if")

    def test_frame_rate_is_frame_rate_json(self):
        for s in sensors():
            with self.subTest(sensor=s.id):
                self.assertEqual(s.frame_rate(), cli_json("frame-rate", s.id, "--json"))
                if "multisampling.samplings" in s.show()["parameters"]:
                    self.assertEqual(s.frame_rate(samplings=3),
                                     cli_json("frame-rate", s.id, "--samplings", "3", "--json"))

    def check_evaluation(self, r, folder):
        """Arrays against the command's CSV files, as the command formats them."""
        header = read_csv(os.path.join(folder, "detectable_area.csv"))
        self.assertEqual(header[0][1:], [g6(v) for v in r.signal])
        self.assertEqual([row[0] for row in header[1:]], [g6(v) for v in r.background])
        self.assertEqual([row[1:] for row in header[1:]], [[r.reasons[c][0] for c in row] for row in r.detect])
        self.assertTrue(np.array_equal(r.detectable, r.detect == 0))
        acc = read_csv(os.path.join(folder, "accuracy_mm.csv"))
        self.assertEqual([row[1:] for row in acc[1:]], [[g6(1e3 * v) for v in row] for row in r.accuracy_m])
        points = read_csv(os.path.join(folder, "points.csv"))
        names = points[0][6:]
        self.assertEqual(names, list(r.metrics))
        ns = len(r.signal)
        for k, line in enumerate(points[1:]):
            b, s = divmod(k, ns)
            expect = [g6(r.signal[s]), g6(r.background[b]), r.reasons[r.detect[b, s]][0],
                      g6(r.sbr_total_dB[b, s]), g6(r.sbr_ratio_dB[b, s]), g6(r.accuracy_m[b, s])]
            expect += [g6(r.metrics[m][b, s]) for m in names]
            self.assertEqual(line, expect, f"points.csv line {k + 1}")
        self.assertGreater(int(r.detectable.sum()), 0, "a grid with nothing detectable checks little")

    def test_evaluate_is_evaluate_files(self):
        for s in sensors():
            sig, bg, sig_text, bg_text = grid(s, 6, 5)
            with self.subTest(sensor=s.id):
                folder = self.out(f"ev-{s.id}")
                rc, _, err = run_cli("evaluate", s.id, "--signal", sig_text, "--background", bg_text, "--no-plots",
                                     "--out", folder)
                self.assertEqual(rc, 0, err)
                with open(os.path.join(folder, "summary.json")) as f:
                    summary = json.load(f)
                r = s.evaluate(signal=sig, background=bg)
                self.assertEqual(r.summary, summary)
                self.check_evaluation(r, folder)
                # The same grid given as the command's text, and through `set`, gives the same result.
                self.assertEqual(s.evaluate(signal=sig_text, background=bg_text).summary, summary)

    def test_evaluate_takes_any_ascending_axes(self):
        # Linear (or any) spacing: every point is evaluated where it was asked for, and equals the
        # command's one-point evaluation there.
        for s in sensors():
            sig, bg, _, _ = grid(s, 6, 5)
            lin = np.linspace(sig[0], sig[-1], 5)
            with self.subTest(sensor=s.id):
                r = s.evaluate(signal=lin, background=bg[[0, 2]])
                np.testing.assert_array_equal(r.signal, lin)
                np.testing.assert_array_equal(r.background, bg[[0, 2]])
                for ib, js in ((0, 1), (1, 3)):
                    v, b = repr(float(lin[js])), repr(float(bg[[0, 2]][ib]))
                    one = s.evaluate(signal=f"{v}:{v}:1", background=f"{b}:{b}:1")
                    self.assertEqual(r.detect[ib, js], one.detect[0, 0])
                    np.testing.assert_array_equal(r.accuracy_m[ib, js], one.accuracy_m[0, 0])



class IdentityTable(CommandCase):
    def test_table_is_table_json(self):
        py = rangesim.table()
        self.assertEqual(py, cli_json("table", "--json"))
        self.assertGreater(py["published_total"], 0)


class IdentityMonteCarlo(CommandCase):
    def test_evaluate_monte_carlo_is_evaluate_trials_files(self):
        for s in sensors():
            sig, bg, sig_text, bg_text = grid(s, 3, 2)
            with self.subTest(sensor=s.id):
                folder = self.out(f"mc-{s.id}")
                rc, _, err = run_cli("evaluate", s.id, "--signal", sig_text, "--background", bg_text, "--trials", "3",
                                     "--seed", "5", "--threads", "2", "--no-plots", "--out", folder)
                self.assertEqual(rc, 0, err)
                with open(os.path.join(folder, "summary.json")) as f:
                    summary = json.load(f)
                r = s.evaluate(signal=sig, background=bg, trials=3, seed=5, threads=2)
                self.assertEqual(r.summary, summary)
                mc = r.monte_carlo
                lines = read_csv(os.path.join(folder, "mc_points.csv"))
                cols = lines[0]
                run = np.argwhere(mc.trials > 0)
                self.assertEqual(len(run), len(lines) - 1)
                self.assertEqual(len(run), int(r.detectable.sum()))
                for (b, sg), line in zip(run, lines[1:]):
                    row = dict(zip(cols, line))
                    self.assertEqual(int(row["trials"]), mc.trials[b, sg])
                    self.assertEqual(int(row["detected"]), mc.detected[b, sg])
                    for name in ("p_detect", "p_detect_lo", "p_detect_hi", "bias_m", "bias_lo_m", "bias_hi_m",
                                 "std_m", "std_lo_m", "std_hi_m", "accuracy_m", "accuracy_lo_m", "accuracy_hi_m"):
                        self.assertEqual(row[name], g9(getattr(mc, name)[b, sg]), f"{name} at ({b}, {sg})")
                self.assertTrue(np.all(np.isnan(mc.accuracy_m[mc.trials == 0])))



class IdentitySimulate(CommandCase):
    def test_simulate_is_simulate_kernel_only_files(self):
        for s in sensors():
            with self.subTest(sensor=s.id):
                scene, r = self.first_scene(s)
                folder = self.out(f"sim-{s.id}")
                rc, out, err = run_cli("simulate", s.id, "--scene", scene, "--seed", "3", "--kernel-only",
                                       "--no-plots", "--points", "--json", "--csv", "--out", folder)
                self.assertEqual(rc, 0, err)
                cli = json.loads(out)
                drop = lambda d: {k: v for k, v in d.items() if k not in WALL_CLOCK_KEYS}
                self.assertEqual(drop(r.summary), drop(cli))
                with open(os.path.join(folder, "frames.csv")) as f:
                    self.assertEqual(r.frames_csv, f.read())
                points = os.path.join(folder, "points.csv")
                if os.path.exists(points):
                    with open(points) as f:
                        self.assertEqual(r.points_csv, f.read())
                else:
                    self.assertEqual(r.points_csv, "")
                rows = read_csv(os.path.join(folder, "range_map.csv"))
                self.assertEqual(rows[0], ["row"] + r.column_names)
                self.assertEqual(rows[1:], [[str(r.first_row + i)] + [g9(v) for v in line]
                                            for i, line in enumerate(r.range_m)])
                self.check_error_map(r, points)

    def check_error_map(self, r, points):
        """validity, truth and error maps: consistent with the range map, and the errors are the
        ones the run scored (points.csv where it has them; the summary's rms for every sensor)."""
        self.assertTrue(np.array_equal(r.valid, np.isfinite(r.range_m)))
        scored = np.isfinite(r.error_m)
        self.assertTrue(np.all(r.valid[scored]) and np.all(np.isfinite(r.truth_m[scored])))
        np.testing.assert_array_equal(r.error_m[scored], (r.range_m - r.truth_m)[scored])
        self.assertGreater(int(scored.sum()), 0)
        rms = float(np.sqrt(np.mean(r.error_m[scored] ** 2)))
        self.assertAlmostEqual(rms, r.summary["range_error_rms_m"], delta=1e-12 + 1e-9 * rms)
        if os.path.exists(points):
            lines = read_csv(points)
            k = lines[0].index("error_m")
            from_csv = sorted(line[k] for line in lines[1:] if line[k])
            self.assertEqual(from_csv, sorted(g9(v) for v in r.error_m[scored]))

    def first_scene(self, s):
        """The first example scene the sensor accepts (the scene reader checks it against the
        sensor's scene rules) and in which some pixel gives a valid range (tof-lockin calls none of
        depth-map.toml's valid: its range noise there is 2.5 m), run by the module with the
        sensor's default frames (one range map)."""
        for name in sorted(os.listdir(SCENES)):
            if not name.endswith(".toml"):
                continue
            path = os.path.join(SCENES, name)
            try:
                r = s.simulate(path, seed=3)
            except rangesim.Error:
                continue
            if np.any(r.valid):
                return path, r
        self.fail(f"no scene in {SCENES} for {s.id}")


if __name__ == "__main__":
    unittest.main()
