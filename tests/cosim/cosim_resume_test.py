#!/usr/bin/env python3
"""`rangesim cosim all` loses nothing: killed with SIGKILL part-way and continued with --resume,
its report equals an uninterrupted run's (wall times aside); Ctrl-C exits 130, keeps the journal
and prints the command that resumes. Usage: cosim_resume_test.py RANGESIM WORKDIR"""
import json, os, shutil, signal, subprocess, sys, time

rangesim, work = sys.argv[1], sys.argv[2]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
base = [rangesim, "cosim", "all", "--cycles", "300", "--seed", "5", "--json"]


def records(journal):
    try:
        with open(journal) as f:
            return sum(1 for line in f if line.startswith("P "))
    except FileNotFoundError:
        return 0


def strip_times(j):
    if isinstance(j, dict):
        return {k: strip_times(v) for k, v in j.items() if k != "wall_time_s"}
    if isinstance(j, list):
        return [strip_times(v) for v in j]
    return j


def start_and_stop(journal, sig, at_least):
    """Starts `all` in its own process group; sends `sig` to the group once the journal holds
    `at_least` targets. Returns (exit code, stderr)."""
    p = subprocess.Popen(base + ["--journal", journal], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         start_new_session=True, text=True)
    t0 = time.time()
    while records(journal) < at_least and p.poll() is None and time.time() - t0 < 300:
        time.sleep(0.05)
    assert p.poll() is None, "the run finished before it could be stopped"
    os.killpg(p.pid, sig)
    _, err = p.communicate(timeout=120)
    return p.returncode, err


ref = subprocess.run(base + ["--journal", f"{work}/ref/all.journal"], capture_output=True, text=True, timeout=600)
assert ref.returncode == 0, ref.stderr
assert not os.path.exists(f"{work}/ref/all.journal"), "a complete run leaves no journal"
want = strip_times(json.loads(ref.stdout))
n_targets = len(want["targets"])

# SIGKILL part-way, then --resume.
journal = f"{work}/killed/all.journal"
code, _ = start_and_stop(journal, signal.SIGKILL, 3)
assert code == -signal.SIGKILL, code
kept = records(journal)
assert 3 <= kept < n_targets, kept
again = subprocess.run(base + ["--journal", journal], capture_output=True, text=True, timeout=60)
assert again.returncode == 2 and "--resume" in again.stderr, again.stderr  # never discards finished work
res = subprocess.run(base + ["--journal", journal, "--resume"], capture_output=True, text=True, timeout=600)
assert res.returncode == 0, res.stderr
assert f"resuming: {kept} of {n_targets} targets" in res.stderr, res.stderr
assert strip_times(json.loads(res.stdout)) == want, "resumed report differs from the uninterrupted run"
assert not os.path.exists(journal)

# Other options are refused on --resume.
journal = f"{work}/other/all.journal"
code, _ = start_and_stop(journal, signal.SIGKILL, 1)
other = subprocess.run([rangesim, "cosim", "all", "--cycles", "301", "--seed", "5", "--json", "--journal", journal,
                        "--resume"], capture_output=True, text=True, timeout=60)
assert other.returncode == 2 and "cycles" in other.stderr, other.stderr

# Ctrl-C: exit 130, journal kept, the printed command finishes the run.
journal = f"{work}/sigint/all.journal"
code, err = start_and_stop(journal, signal.SIGINT, 2)
assert code == 130, (code, err)
assert "--resume" in err and records(journal) >= 2, err
res = subprocess.run(base + ["--journal", journal, "--resume"], capture_output=True, text=True, timeout=600)
assert res.returncode == 0 and strip_times(json.loads(res.stdout)) == want, res.stderr
print(f"OK: {n_targets} targets; killed with {kept} kept, resumed identical; SIGINT exit 130 resumed identical")
