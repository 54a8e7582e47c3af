#!/usr/bin/env python3
"""A Python testbench around one clock kernel: the ls-conventional row address search.

The kernel (rangesim.kernels.AddressSearch, made from the preset) is the device under test here,
driven cycle by cycle the way a cocotb testbench drives RTL: a driver applies start and the row's
activation bits, a monitor turns the pins it sees each cycle (busy, addr_valid, addr_bit, done)
into transactions, and a scoreboard compares them in order with a pure-Python model of the
block's transactions (found, left and right edge, cycles from start to done). The same loop
works with the model as the reference and RTL as the device (docs/python.md).

    PYTHONPATH=build/python python3 examples/python/testbench.py [--operations N] [--seed S]
        [--set KEY=VALUE ...] [--inject-fault addr-bit|model-edges]

Exit code 0 when every transaction matched, 1 when the scoreboard found mismatches.
"""
import argparse
import random
import sys

import rangesim


class SearchModel:
    """What one search operation does, from the block's description (ARCHITECTURE.md, docs/cosim.md):
    the leftmost and rightmost activated columns, streamed as two address_bits-wide addresses after
    search_cycles of settling; a row without activation ends after the settling alone."""

    def __init__(self, search_cycles, address_bits, swap_edges=False):
        self.search_cycles = search_cycles
        self.address_bits = address_bits
        self.swap_edges = swap_edges  # an injected fault in the model: the checker must see it

    def transaction(self, bits):
        active = [c for c, b in enumerate(bits) if b]
        if not active:
            return {"found": False, "left": 0, "right": 0, "cycles": self.search_cycles}
        left, right = active[0], active[-1]
        if self.swap_edges:
            left, right = right, left
        return {"found": True, "left": left, "right": right, "cycles": self.search_cycles + 2 * self.address_bits}


class Monitor:
    """Rebuilds transactions from the pins, cycle by cycle: addr_bit is sampled while addr_valid,
    the operation ends with done."""

    def __init__(self, address_bits):
        self.address_bits = address_bits
        self.bits = []
        self.start_cycle = None

    def started(self, cycle):
        self.bits, self.start_cycle = [], cycle

    def sample(self, cycle, pins):
        if pins.addr_valid:
            self.bits.append(1 if pins.addr_bit else 0)
        if not pins.done:
            return None
        word = 0
        for b in self.bits:
            word = (word << 1) | b
        mask = (1 << self.address_bits) - 1
        found = len(self.bits) == 2 * self.address_bits
        return {
            "found": pins.found,
            "left": (word >> self.address_bits) & mask if found else 0,
            "right": word & mask if found else 0,
            "cycles": cycle - self.start_cycle,
        }


def random_row(rng, columns):
    """Empty rows, single pixels, runs and scattered pixels, as a light section produces them."""
    bits = [False] * columns
    kind = rng.random()
    if kind < 0.15:
        return bits
    if kind < 0.35:
        bits[rng.randrange(columns)] = True
        return bits
    if kind < 0.85:
        start = rng.randrange(columns)
        for c in range(start, min(columns, start + rng.randint(1, 12))):
            bits[c] = True
        return bits
    for _ in range(rng.randint(2, 6)):
        bits[rng.randrange(columns)] = True
    return bits


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--preset", default="ls-conventional")
    ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE")
    ap.add_argument("--operations", type=int, default=300)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--inject-fault", choices=["addr-bit", "model-edges"])
    ap.add_argument("--show", type=int, default=5, help="transactions to print")
    args = ap.parse_args()

    sensor = rangesim.load(args.preset, set=args.set)
    dut = sensor.kernel("address_search")
    model = SearchModel(dut.search_cycles, dut.address_bits, swap_edges=args.inject_fault == "model-edges")
    monitor = Monitor(dut.address_bits)
    rng = random.Random(args.seed)
    print(f"testbench: {sensor.id} address_search, {dut.columns} columns, {dut.address_bits} address bits, "
          f"search {dut.search_cycles} cycles; {args.operations} operations, seed {args.seed}"
          + (f", fault {args.inject_fault}" if args.inject_fault else ""))

    dut.tick(rst=True)
    cycle, budget = 0, args.operations * (dut.operation_cycles(True) + 8) + 10  # every run is bounded
    expected, actual, mismatches = [], [], []
    flip_at = None
    for op in range(args.operations):
        for _ in range(rng.randint(0, 3)):  # idle cycles between operations
            dut.tick()
            cycle += 1
        bits = random_row(rng, dut.columns)
        expected.append(model.transaction(bits))
        pins = dut.tick(start=True, act=rangesim.kernels.ActivationRow(bits))  # latched at this edge
        cycle += 1
        monitor.started(cycle - 1)
        if args.inject_fault == "addr-bit" and flip_at is None and op >= args.operations // 2 and any(bits):
            flip_at = cycle + dut.search_cycles + 3  # one address bit flipped on its way to the monitor
        got = None
        while got is None:
            if cycle > budget:
                print(f"testbench: no done within the cycle budget {budget}", file=sys.stderr)
                return 1
            if cycle == flip_at:
                pins = FlippedBit(pins)
            got = monitor.sample(cycle, pins)
            pins = dut.tick()
            cycle += 1
        actual.append(got)
        if got != expected[-1]:
            active = [c for c, b in enumerate(bits) if b]
            shown = ", ".join(map(str, active[:8])) + (", ..." if len(active) > 8 else "")
            mismatches.append(f"operation {op} (cycle {monitor.start_cycle}, active columns [{shown}]): "
                              f"expected {expected[-1]}, got {got}")

    for k in range(min(args.show, len(actual))):
        print(f"  transaction {k}: {actual[k]}")
    print(f"testbench: {len(actual)} transactions over {cycle} cycles, {len(mismatches)} mismatch(es)")
    for m in mismatches[:10]:
        print("  MISMATCH " + m)
    return 1 if mismatches else 0


class FlippedBit:
    """The pins of one cycle with addr_bit inverted (the addr-bit fault)."""

    def __init__(self, pins):
        self._pins = pins

    def __getattr__(self, name):
        value = getattr(self._pins, name)
        return (not value) if name == "addr_bit" and self._pins.addr_valid else value


if __name__ == "__main__":
    sys.exit(main())
