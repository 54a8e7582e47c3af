#!/usr/bin/env python3
"""`rangesim bench` loses nothing: killed with SIGKILL part-way and continued with --resume, the
rows it had finished are kept exactly (not measured again), the deterministic results (errors,
frames, points, identity checks) equal an uninterrupted run's, and the output folder holds only
the outputs. Ctrl-C exits 130 and prints the command that resumes.
Usage: bench_resume_test.py RANGESIM WORKDIR"""
import csv, json, os, shutil, signal, subprocess, sys, time

rangesim, work = sys.argv[1], sys.argv[2]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)


def bench(out, *extra):
    return subprocess.run([rangesim, "bench", "--quick", "--json", "--out", out, *extra], capture_output=True, text=True,
                          timeout=1200)


def journal_records(out):
    try:
        with open(f"{out}/.staging-sweep/bench.journal") as f:
            return [line for line in f if line.startswith("P ")]
    except FileNotFoundError:
        return []


def stop_after(out, sig, n):
    p = subprocess.Popen([rangesim, "bench", "--quick", "--json", "--out", out], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, start_new_session=True, text=True)
    t0 = time.time()
    while len(journal_records(out)) < n and p.poll() is None and time.time() - t0 < 600:
        time.sleep(0.05)
    assert p.poll() is None, "bench finished before it could be stopped"
    os.killpg(p.pid, sig)
    _, err = p.communicate(timeout=120)
    return p.returncode, err


def deterministic(rows):
    return [(r["sensor"], r["setting"], r["frames"], r["error_rms_m"]) for r in rows]


ref = bench(f"{work}/ref")
assert ref.returncode == 0, ref.stderr
want = json.loads(ref.stdout)

out = f"{work}/killed"
code, _ = stop_after(out, signal.SIGKILL, 2)
assert code == -signal.SIGKILL, code
kept = [json.loads(line.split(" ", 3)[3].rsplit(" ", 1)[0]) for line in journal_records(out)]
assert len(kept) >= 2
res = bench(out, "--resume")
assert res.returncode == 0, res.stderr
got = json.loads(res.stdout)
assert f"resuming: {len(kept)} results" in res.stderr, res.stderr
rows = got["pareto"]
for k in kept:  # the finished rows come back exactly, CPU times included: not measured again
    match = [r for r in rows if r["sensor"] == k["sensor"] and r["setting"] == k["setting"]]
    assert match and match[0]["cpu_s"] == k["cpu_s"] and match[0]["wall_s"] == k["wall_s"], (k, match)
assert deterministic(rows) == deterministic(want["pareto"]), "resumed results differ from the uninterrupted run"
assert got["checks"] == want["checks"] and got["checks_passed"], got["checks"]
assert sorted(os.listdir(out)) == sorted(os.listdir(f"{work}/ref")), (os.listdir(out), os.listdir(f"{work}/ref"))

out = f"{work}/sigint"
code, err = stop_after(out, signal.SIGINT, 1)
assert code == 130 and "--resume" in err, (code, err)
assert not bench(out).returncode == 0, "a journal must not be discarded without --resume"
print(f"OK: killed with {len(kept)} results kept, resumed with them unchanged and the rest identical; SIGINT exit 130")
