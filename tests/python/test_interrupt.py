"""Long calls release the GIL and stop on Ctrl-C: a child process starts one, gets SIGINT, and must
raise KeyboardInterrupt within a couple of seconds instead of running to the end."""
import os
import signal
import subprocess
import sys
import time
import unittest

from rangesim_test_util import SCENES

CHILD = r"""
import sys, threading, time
import rangesim
call = sys.argv[1]
s = rangesim.load(sys.argv[2])
# Another Python thread keeps running while the C++ works: the GIL is released.
ticks = []
threading.Thread(target=lambda: [ticks.append(time.sleep(0.01)) for _ in range(100000)], daemon=True).start()
print("started", flush=True)
t = time.time()
try:
    if call == "evaluate":
        s.evaluate(signal=sys.argv[3], background=sys.argv[4])
    elif call == "monte_carlo":
        s.evaluate(signal=sys.argv[3], background=sys.argv[4], trials=1000000, threads=2)
    elif call == "simulate":
        s.simulate(sys.argv[3], frames=int(sys.argv[4]))
    elif call == "table":
        rangesim.table()
    print("finished %.2f" % (time.time() - t))
except KeyboardInterrupt:
    print("interrupted %.2f ticks %d" % (time.time() - t, len(ticks)))
"""

# Each call runs for several seconds at least uninterrupted (the table ~9 s, the others minutes).
CASES = {
    "evaluate": ["ls-conventional", "0.001:1.5:600", "0.001:1:600"],
    "monte_carlo": ["tof-spad", "100:1e6:4", "10:1e8:3"],
    "simulate": ["tof-spad", os.path.join(SCENES, "tof-spad-plane.toml"), "5000"],
    "table": ["ls-conventional"],
}


class Interrupt(unittest.TestCase):
    def test_ctrl_c_stops_long_calls(self):
        for call, args in CASES.items():
            with self.subTest(call=call):
                p = subprocess.Popen([sys.executable, "-B", "-c", CHILD, call, *args], stdout=subprocess.PIPE,
                                     stderr=subprocess.PIPE, text=True)
                self.assertEqual(p.stdout.readline().strip(), "started")
                time.sleep(1.0)
                sent = time.time()
                p.send_signal(signal.SIGINT)
                try:
                    out, err = p.communicate(timeout=20)
                except subprocess.TimeoutExpired:
                    p.kill()
                    self.fail(f"{call}: still running 20 s after SIGINT")
                waited = time.time() - sent
                self.assertIn("interrupted", out, f"{call}: {out} {err}")
                self.assertLess(waited, 5.0, f"{call}: took {waited:.1f} s to stop")
                ticks = int(out.split()[-1])
                self.assertGreater(ticks, 20, f"{call}: the other Python thread did not run")


if __name__ == "__main__":
    unittest.main()
