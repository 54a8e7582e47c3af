"""Checks a `rangesim cosim --trace` VCD: the RTL (Verilator) and, under the top-level scope
"expected", the model's values of the signals the target's scoreboard compares; every value change
refers to a declared identifier and the times increase. Beside it, the GTKWave save file
(tb/common/cosim_save_file.h): every signal it names is declared in the trace, every compared
signal is in the "checked" group right below its RTL counterpart, and the translate filters it
uses exist. Prints OK and the expected signals.

usage: check_trace_expected.py TRACE.vcd TARGET
"""
import sys

# The compared signals each target's expected scope must hold (scope.signal below "expected").
REQUIRED = {
    "ls-demodulation": ["sequencer.phase", "sequencer.row", "readout.row_valid", "readout.found", "readout.left",
                        "readout.right"],
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


def check_save_file(path, target, full_names):
    """full_names: every declared variable as GTKWave names it (scopes.name[range])."""
    import os
    gtkw = path[:-4] + ".gtkw"
    assert os.path.exists(gtkw), "no save file " + gtkw
    refs, filters, group, checked = [], [], None, []
    pending_filter = None
    for line in open(gtkw):
        line = line.rstrip("\n")
        if line.startswith("^1 "):
            pending_filter = line[3:]
            filters.append(pending_filter)
        elif line.startswith("-"):
            group = None if group == line[1:] else line[1:]
        elif line and line[0] not in "@[*":
            refs.append(line)
            if group and group.startswith("checked"):
                checked.append((line, pending_filter))
            pending_filter = None
    unknown = [r for r in refs if r not in full_names]
    assert not unknown, ("save file names undeclared signals", unknown[:10])
    for f in set(filters):
        assert os.path.exists(os.path.join(os.path.dirname(gtkw), f)), "missing filter " + f
    # Each compared signal sits in the checked group, preceded by an RTL signal (its counterpart).
    names = [c[0] for c in checked]
    for s in REQUIRED[target]:
        hits = [i for i, n in enumerate(names) if n.split("[")[0] == "expected." + s]
        assert hits, ("compared signal not in the checked group", s)
        i = hits[0]
        assert i > 0 and not names[i - 1].startswith("expected."), ("no RTL counterpart above", s)
        assert checked[i - 1][1] == checked[i][1], ("RTL and expected decoded differently", s)
    return len(refs)


def main(path, target):
    decl, scope, header, bad, last, ordered = {}, [], True, 0, -1, True
    full = set()
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
                rng = "".join(w for w in t[5:] if w != "$end")
                full.add(".".join(scope + [t[4]]) + rng)
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
    shown = check_save_file(path, target, full)
    print("OK", target, len(names), "signals,", len(REQUIRED[target]), "compared signals under expected,", shown,
          "in the save file")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
