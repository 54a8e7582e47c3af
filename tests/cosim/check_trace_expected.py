"""Checks a `rangesim cosim --trace` VCD: the RTL (Verilator) and, under the top-level scope
"expected", the model's values of the signals the target's scoreboard compares; every value change
refers to a declared identifier and the times increase. Prints OK and the expected signals.

usage: check_trace_expected.py TRACE.vcd TARGET
"""
import sys

# The compared signals each target's expected scope must hold (scope.signal below "expected").
REQUIRED = {
    "tof-lockin": ["sequencer.phase", "sequencer.tx1", "sequencer.tx2", "sequencer.txd", "sequencer.light",
                   "sequencer.row", "sequencer.frame", "adc0.ramp", "adc0.code", "adc1.code"],
    "tof-spad": ["sequencer.phase", "sequencer.row", "tdc.event", "tdc.overflow", "tdc.lost", "tdc.grant",
                 "tdc.code", "histogram.word_valid", "histogram.word", "histogram.peak_code",
                 "histogram.peak_count", "histogram.centroid_num", "histogram.centroid_den"],
    "tdc": ["tdc.event", "tdc.overflow", "tdc.lost", "tdc.grant", "tdc.code", "histogram.word"],
    "address_search": ["address_search.busy", "address_search.found", "address_search.addr_valid",
                       "address_search.addr_bit", "address_search.done"],
    "centre_processor": ["centre_processor.valid", "centre_processor.centre_q", "centre_processor.sum",
                         "centre_processor.count"],
    "multisampling_sequencer": ["sequencer.phase", "sequencer.pix_reset", "sequencer.latch",
                                "sequencer.search_start", "sequencer.frame_done", "sequencer.sampling",
                                "sequencer.frame"],
    "lockin_gate_generator": ["gates.busy", "gates.tx1", "gates.tx2", "gates.txd", "gates.light", "gates.last"],
    "column_adc": ["adc.busy", "adc.ramp", "adc.done", "adc.code"],
}


def main(path, target):
    decl, scope, header, bad, last, ordered = {}, [], True, 0, -1, True
    changes = {}
    for line in open(path):
        t = line.split()
        if not t:
            continue
        if header:
            if t[0] == "$scope":
                scope.append(t[2])
            elif t[0] == "$upscope":
                scope.pop()
            elif t[0] == "$var":
                decl[t[3]] = ".".join(scope + [t[4]])
            elif t[0] == "$enddefinitions":
                header = False
            continue
        if t[0][0] == "#":
            ordered = ordered and int(t[0][1:]) > last
            last = int(t[0][1:])
            continue
        if t[0][0] == "$":
            continue
        i = t[1] if t[0][0] in "bBrR" else t[0][1:]
        bad += i not in decl
        changes[i] = changes.get(i, 0) + 1
    names = set(decl.values())
    assert bad == 0 and ordered, (bad, ordered)
    assert any(not n.startswith("expected.") for n in names), "no RTL signals"
    missing = [s for s in REQUIRED[target] if "expected." + s not in names]
    assert not missing, (missing, sorted(n for n in names if n.startswith("expected."))[:40])
    # The model's values move: at least one expected signal changes after time 0.
    moving = [decl[i] for i, n in changes.items() if decl[i].startswith("expected.") and n > 1]
    assert moving, "the expected signals never change"
    print("OK", target, len(names), "signals,", len(REQUIRED[target]), "compared signals under expected")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
