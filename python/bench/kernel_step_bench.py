#!/usr/bin/env python3
"""Per-step cost of the clock kernels from Python against the same loops in C++.

Runs each loop of python/bench/kernel_step_bench.cpp through the module (the kernels made from the
same presets, the same inputs, one step = one call that advances the kernel and reads what the
loop needs of its outputs), runs the C++ executable for the reference, and prints ns per step
both ways and the difference (the cost of crossing into Python and back). docs/python.md reports
a run.

    PYTHONPATH=build/python python3 python/bench/kernel_step_bench.py [--steps N] [--cpp-steps M]
        [--cpp build/python/rangesim-kernel-step-bench] [--json]
"""
import argparse
import json
import os
import subprocess
import time

import numpy as np

import rangesim
from rangesim.kernels import ActivationRow


def best_ns(steps, run):
    """ns per step of run(steps), best of three (as the C++ side)."""
    best = float("inf")
    for _ in range(3):
        t0 = time.perf_counter_ns()
        run(steps)
        best = min(best, (time.perf_counter_ns() - t0) / steps)
    return best


def block_presets():
    """The preset each timed block is made from: the first sensor rangesim.kernels.blocks() lists
    for it (the C++ loops get the same, as BLOCK=PRESET)."""
    presets = {}
    for b in rangesim.kernels.blocks():
        presets.setdefault(b["block"], b["sensor"])
    return presets


def python_steps(steps, presets):
    def kernel(block):
        return rangesim.load(presets[block]).kernel(block)

    search = kernel("address_search")
    row = ActivationRow(search.columns)
    row.set(40)
    row.set(48)
    sink = [0]

    def address_search(n):
        k = kernel("address_search")
        s = 0
        for _ in range(n):
            s += k.tick(False, k.idle, row).addr_bit
        sink[0] += s

    def sequencer(n):
        k = kernel("multisampling_sequencer")
        s = 0
        for _ in range(n):
            s += k.tick().sampling
        sink[0] += s

    def gate(n):
        g = kernel("lockin_gate_generator")
        g.start()
        s = 0
        for _ in range(n):
            if g.done:
                g.start()
            s += g.advance(1) + g.tx1
        sink[0] += s

    adc = kernel("column_adc")

    def adc_scalar(n):
        s = 0
        for i in range(n):
            s += adc.code((i & 1023) * 1e-3)
        sink[0] += s

    volts = (np.arange(steps) & 1023) * 1e-3

    def adc_array(n):
        sink[0] += int(adc.codes(volts[:n]).sum())

    def tdc_hits(n):
        t = kernel("tdc")
        cols, bins, cycles = t.columns, t.phase_bins, t.laser_cycles
        cycle, s = 0, 0
        for i in range(n):
            if cycle == cycles:
                t.reset()
                cycle = 0
            s += t.hit(i % cols, cycle, i % bins).code
            cycle += 1
        sink[0] += s

    # (step, its C++ loop in kernel_step_bench.cpp, ns per step from Python)
    return [
        ("address_search.tick", "address_search.tick", best_ns(steps, address_search)),
        ("multisampling_sequencer.tick", "multisampling_sequencer.tick", best_ns(steps, sequencer)),
        ("lockin_gate_generator.advance", "lockin_gate_generator.advance", best_ns(steps, gate)),
        ("column_adc.code", "column_adc.code", best_ns(steps, adc_scalar)),
        ("column_adc.codes, per element of one array", "column_adc.code", best_ns(steps, adc_array)),
        ("tdc.hit", "tdc.hit", best_ns(steps, tdc_hits)),
    ]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--steps", type=int, default=300000, help="steps per loop from Python")
    ap.add_argument("--cpp-steps", type=int, default=20000000, help="steps per loop in C++")
    ap.add_argument("--cpp", default=os.path.join(os.path.dirname(rangesim.__file__), "rangesim-kernel-step-bench"),
                    help="the C++ executable (built beside the module)")
    ap.add_argument("--json", action="store_true")
    args = ap.parse_args()

    presets = block_presets()
    cpp = json.loads(subprocess.run([args.cpp, str(args.cpp_steps)] + [f"{b}={p}" for b, p in presets.items()],
                                    capture_output=True, text=True, check=True).stdout)
    py = python_steps(args.steps, presets)
    rows = []
    for name, reference, ns in py:
        base = cpp[reference]["ns_per_step"]
        rows.append({"step": name, "python_ns": ns, "cpp_ns": base, "overhead_ns": ns - base, "ratio": ns / base})
    if args.json:
        print(json.dumps({"python_steps": args.steps, "cpp_steps": args.cpp_steps, "rows": rows}, indent=2))
        return
    print(f"{'step':46} {'C++ ns':>9} {'Python ns':>10} {'overhead ns':>12} {'ratio':>7}")
    for r in rows:
        print(f"{r['step']:46} {r['cpp_ns']:9.2f} {r['python_ns']:10.1f} {r['overhead_ns']:12.1f} {r['ratio']:7.0f}x")
    print(f"({args.steps} steps per loop from Python, {args.cpp_steps} in C++, best of three; "
          f"{rangesim.__file__})")


if __name__ == "__main__":
    main()
