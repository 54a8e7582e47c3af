"""The readout kernels from Python: made from presets, driven cycle by cycle and transaction by
transaction, and agreeing with the preset's clock schedule and with their own closed forms."""
import random
import unittest

import numpy as np

import rangesim
from rangesim.kernels import ActivationRow


class Kernels(unittest.TestCase):
    def test_blocks_listed_per_sensor(self):
        blocks = rangesim.kernels.blocks()
        for p in rangesim.presets():
            s = rangesim.load(p["id"])
            self.assertEqual(s.kernels(), [b["block"] for b in blocks if b["sensor"] == s.id])
        self.assertEqual({b["block"] for b in blocks},
                         {"multisampling_sequencer", "address_search", "centre_processor", "lockin_gate_generator",
                          "column_adc", "tdc"})

    def test_demodulation_search_is_its_readout(self):
        # The row search the ls-demodulation kernel time-multiplexes: as wide as the array, settling
        # for what the row readout leaves after start and the two streamed addresses.
        s = rangesim.load("ls-demodulation", set={"pixel.columns": 64})
        p = {k: v["value"] for k, v in s.show()["parameters"].items()}
        k = s.kernel("address_search")
        self.assertEqual((k.columns, k.address_bits), (64, p["readout.address_bits"]))
        self.assertEqual(k.search_cycles, p["readout.row_cycles"] - 1 - 2 * p["readout.address_bits"])
        row = ActivationRow([c in (10, 20) for c in range(64)])
        r = k.run(row)
        self.assertEqual((r.found, r.left, r.right), (True, 10, 20))

    def test_kernels_follow_set(self):
        s = rangesim.load("ls-conventional", set={"pixel.columns": 100, "timing.address_bits": 7})
        k = s.kernel("address_search")
        self.assertEqual((k.columns, k.address_bits), (100, 7))

    def test_address_search_ticks_against_closed_form(self):
        k = rangesim.load("ls-conventional").kernel("address_search")
        rng = random.Random(3)
        for _ in range(50):
            bits = [rng.random() < 0.02 for _ in range(k.columns)]
            row = ActivationRow(bits)
            self.assertEqual(row.first(), bits.index(True) if any(bits) else -1)
            ran, closed = k.run(row), k.evaluate(row)
            self.assertEqual((ran.found, ran.left, ran.right, ran.done_cycle),
                             (closed.found, closed.left, closed.right, closed.done_cycle))
            self.assertEqual(ran.done_cycle, k.operation_cycles(any(bits)))
            self.assertTrue(k.idle)
        # Pin by pin: busy from the start edge until done, addr_valid for exactly 2 B cycles.
        bits = np.zeros(k.columns, bool)
        bits[[5, 9]] = True
        pins = [k.tick(start=True, act=bits)]
        while not pins[-1].done:
            pins.append(k.tick())
        self.assertEqual(len(pins), k.operation_cycles(True))
        self.assertTrue(all(p.busy for p in pins))
        self.assertEqual(sum(p.addr_valid for p in pins), 2 * k.address_bits)

    def test_centre_processor_cycle_by_cycle_equals_transactions(self):
        s = rangesim.load("ls-conventional")
        search, by_cycle, by_transaction = (s.kernel("address_search"), s.kernel("centre_processor"),
                                            s.kernel("centre_processor"))
        rng = random.Random(5)
        by_cycle.tick(clear=True)
        for _ in range(4):  # four samplings of one frame access
            bits = np.zeros(search.columns, bool)
            c = rng.randrange(search.columns - 10)
            bits[c:c + rng.randint(1, 9)] = True
            by_transaction.accumulate(search.evaluate(bits))
            pins = search.tick(start=True, act=bits)
            while True:
                by_cycle.tick(search=pins)
                if pins.done:
                    break
                pins = search.tick()
            search.tick()
        self.assertEqual(by_cycle.pins, by_transaction.pins)
        p = by_cycle.pins
        self.assertTrue(p.valid)
        self.assertEqual(p.count, 4)
        self.assertEqual(p.exact_centre_px, p.sum / 8)
        self.assertAlmostEqual(p.centre_px, p.exact_centre_px, delta=1 / 256)

    def test_sequencer_phases_are_the_frame_rate_schedule(self):
        s = rangesim.load("ls-conventional", set={"multisampling.samplings": 3})
        seq = s.kernel("multisampling_sequencer")
        schedule = s.frame_rate()
        self.assertEqual(seq.frame_cycles, schedule["frame_cycles"])
        cycles = {}
        pins = seq.pins
        for _ in range(seq.frame_cycles):
            cycles[pins.phase] = cycles.get(pins.phase, 0) + 1
            pins = seq.tick()
        self.assertEqual(cycles, {p["name"]: p["cycles"] for p in schedule["phases"] if p["cycles"]})
        self.assertEqual(pins.frame, 1)
        # Event skipping lands on the same pins as ticking.
        other = s.kernel("multisampling_sequencer")
        self.assertEqual(other.advance_to(seq.cycle), pins)

    def test_gate_generator_covers_the_accumulations(self):
        g = rangesim.load("tof-lockin").kernel("lockin_gate_generator")
        g.start()
        counts, closed, steps = {}, 0, 0
        while not g.done:
            n = g.cycles_to_edge()
            counts[g.phase] = counts.get(g.phase, 0) + n
            self.assertEqual(g.light, g.tx1)
            self.assertEqual(g.tx1 + g.tx2 + g.txd, 1)
            closed += g.advance(n)
            steps += 1
        self.assertEqual(counts["phase1"], g.t0_cycles * g.accumulations)
        self.assertEqual(counts["phase2"], g.t0_cycles * g.accumulations)
        self.assertEqual(sum(counts.values()), g.period_cycles * g.accumulations)
        self.assertEqual(closed, 3 * g.accumulations)
        g.start()
        g.advance(1)
        self.assertEqual(g.finish_all(), g.period_cycles * g.accumulations - 1)

    def test_column_adc(self):
        adc = rangesim.load("tof-lockin").kernel("column_adc")
        v = np.array([0.0, adc.lsb_V * 2.5, 1e3, -1.0])
        codes = adc.codes(v)
        self.assertEqual(list(codes), [adc.code(x) for x in v])
        self.assertEqual(list(codes), [0, 2, adc.top_code, 0])
        self.assertEqual(adc.value_V(2), 2 * adc.lsb_V)

    def test_tdc_transactions(self):
        tdc = rangesim.load("tof-spad").kernel("tdc")
        self.assertGreater(tdc.block_event_bins, 0)
        first = tdc.hit(0, 0, 3)
        self.assertEqual((first.kind, first.abs_bin, first.code), ("event", 3, 3))
        # Inside the dead time, another column's hit is lost; after it, the next START re-arms.
        self.assertEqual(tdc.hit(1, 0, min(3 + 1, tdc.phase_bins - 1)).kind, "lost")
        later = (tdc.block_event_bins + 3) // tdc.phase_bins + 1
        self.assertEqual(tdc.hit(1, later, 5).kind, "event" if 5 < tdc.codes else "overflow")
        if tdc.codes < tdc.phase_bins:
            self.assertEqual(tdc.hit(0, later + 2 + tdc.block_event_bins // tdc.phase_bins, tdc.codes).kind,
                             "overflow")
        h = tdc.finish()
        self.assertEqual(h.events.shape, (tdc.columns, tdc.codes))
        self.assertEqual((h.events[0, 3], h.events[1, 5]), (1, 1))
        self.assertEqual(h.starts, tdc.laser_cycles)
        self.assertLessEqual(int(h.armed.max()), tdc.laser_cycles)
        with self.assertRaises(rangesim.Error):
            tdc.hit(0, 0, 0)
        tdc.reset()
        self.assertEqual(tdc.hit(0, 0, 0).kind, "event")
        self.assertEqual(tdc.phase_bin(0.0), 0)


if __name__ == "__main__":
    unittest.main()
