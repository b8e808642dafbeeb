#!/usr/bin/env python3
"""Tests of the dEQP runner (deqp-lists/run.py, `./fixpipe deqp`) with a fake dEQP.

tests/harness/fake-deqp decides each case's outcome from its name (and crashes or hangs on
request); tests/harness/fake-launcher stands in for `./fixpipe run`.  Ends with
'harness-deqp: N passed, N failed'.
"""
import csv
import json
import os
import shutil
import subprocess
import sys
import tempfile

from tally import Tally

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
RUNNER = os.path.join(REPO, "deqp-lists", "run.py")

T = Tally(indent="  ")
check = T.check


G = "dEQP-GLES2.functional.fake"
CASES = [f"{G}.a.pass_1", f"{G}.a.pass_2", f"{G}.b.fail_known", f"{G}.b.pass_was_failing",
         f"{G}.c.crash_here", f"{G}.c.pass_after_crash", f"{G}.d.hang_here",
         f"{G}.d.pass_after_hang", f"{G}.e.notsupported_1", f"{G}.e.warn_1",
         f"{G}.f.flaky_1", f"{G}.g.pass_excluded", "dEQP-GLES2.performance.x.pass_1"]
FAILS = f"""# planted: the fake fails it
{G}.b.fail_known,Fail
# fixed since: must be reported
{G}.b.pass_was_failing,Fail
# the fake aborts in it
{G}.c.crash_here,Crash
# the fake sleeps in it
{G}.d.hang_here,Timeout
"""


class Run:
    def __init__(self, cases=CASES, fails=FAILS, skips="# too slow\n\\.pass_excluded$\n",
                 mustpass_exclude=None):
        self.tmp = tempfile.TemporaryDirectory(prefix="fixpipe-deqp-harness-")
        d = self.tmp.name
        mdir = os.path.join(d, "build", "modules", "gles2")
        os.makedirs(mdir)
        shutil.copy(os.path.join(HERE, "fake-deqp"), os.path.join(mdir, "deqp-gles2"))
        self.cases = os.path.join(d, "cases.txt")
        with open(self.cases, "w") as f:
            f.write("".join(c + "\n" for c in cases))
        self.exp = os.path.join(d, "exp")
        os.makedirs(self.exp)
        for kind, text in (("fails", fails), ("skips", skips)):
            with open(os.path.join(self.exp, f"llvmpipe-{kind}.txt"), "w") as f:
                f.write(text)
        self.out = os.path.join(d, "out")
        self.build = os.path.join(d, "build")

    def run(self, *extra, env=None):
        e = dict(os.environ, DEQP_BUILD=self.build, FAKE_DEQP_CASES=self.cases, **(env or {}))
        cmd = [sys.executable, RUNNER, "gles2", "--driver", "llvmpipe", "--list", "all",
               "--out", self.out, "--expectations", self.exp, "--timeout", "3",
               "--launcher", os.path.join(HERE, "fake-launcher"), *extra]
        p = subprocess.run(cmd, env=e, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           text=True, timeout=120)
        self.rc, self.output = p.returncode, p.stdout
        return self

    def summary(self, sub="llvmpipe-gles2-all"):
        with open(os.path.join(self.out, sub, "summary.json")) as f:
            return json.load(f)


def test_results_and_expectations():
    r = Run().run("--jobs", "2", "--chunk", "3")
    s = r.summary()
    t = s["tests"]
    check("a crash restarts the process after the crashing case",
          t[f"{G}.c.crash_here"]["result"] == "crash"
          and t[f"{G}.c.pass_after_crash"]["result"] == "pass", r.output)
    check("a hang is killed at the timeout and the chunk goes on",
          t[f"{G}.d.hang_here"]["result"] == "timeout"
          and t[f"{G}.d.pass_after_hang"]["result"] == "pass", r.output)
    check("performance and stress cases are not in the list 'all'",
          "dEQP-GLES2.performance.x.pass_1" not in t)
    check("skips are not run, and counted apart",
          t[f"{G}.g.pass_excluded"]["result"] == "excluded" and s["counts"]["excluded"] == 1)
    check("NotSupported and QualityWarning are their own results",
          t[f"{G}.e.notsupported_1"]["result"] == "notsupported"
          and t[f"{G}.e.warn_1"]["result"] == "warn")
    check("a failure that passes alone is a flake, not fatal",
          t[f"{G}.f.flaky_1"]["result"] == "flake", r.output)
    check("an expected failure that passes fails the run until its line goes",
          t[f"{G}.b.pass_was_failing"]["status"] == "unexpected_pass" and r.rc == 1
          and "UnexpectedPass" in r.output, r.output)
    check("the summary line counts the cases run that met their expectation; skips apart",
          "deqp-gles2-llvmpipe: 9 passed, 1 failed, 2 skipped" in r.output, r.output)
    with open(os.path.join(r.out, "llvmpipe-gles2-all", "results.csv")) as f:
        rows = {row["test"]: row["status"] for row in csv.DictReader(f)}
    check("results.csv has every case with dEQP's status",
          len(rows) == 12 and rows[f"{G}.a.pass_1"] == "Pass"
          and rows[f"{G}.c.crash_here"] == "Crash" and rows[f"{G}.f.flaky_1"] == "Flake", rows)
    qpa = os.path.join(r.out, "llvmpipe-gles2-all", "qpa", f"{G}.b.fail_known.qpa")
    check("the QPA log of a failure is kept",
          os.path.exists(qpa) and "StatusCode=\"Fail\"" in open(qpa).read())
    check("no QPA log of a pass",
          not os.path.exists(os.path.join(os.path.dirname(qpa), f"{G}.a.pass_1.qpa")))


def test_new_failure_fails():
    fails = FAILS.replace(f"# planted: the fake fails it\n{G}.b.fail_known,Fail\n", "")
    fails = fails.replace(f"# fixed since: must be reported\n{G}.b.pass_was_failing,Fail\n", "")
    r = Run(fails=fails).run()
    check("a new failure is reported and fails the run",
          r.rc == 1 and f"FAIL     {G}.b.fail_known" in r.output, r.output)
    r = Run(fails=fails.replace("Crash", "Fail")).run()
    check("a crash where a failure is expected fails the run",
          r.rc == 1 and f"CRASH    {G}.c.crash_here" in r.output, r.output)
    r = Run(fails=FAILS.replace(f"{G}.b.pass_was_failing,Fail\n", "")
            .replace("# fixed since: must be reported\n", "")).run()
    check("every expectation met: exit 0", r.rc == 0, r.output)


def test_bad_input():
    r = Run(fails=f"{G}.b.fail_known,Fail\n").run()
    check("an expectation without a reason is an input error",
          r.rc == 2 and "no '# reason' line" in r.output, r.output)
    r = Run(fails=f"# why\n{G}.b.fail_known,Broken\n").run()
    check("an unknown expected status is an input error", r.rc == 2, r.output)
    r = Run().run(env={"FAKE_DEQP_NOSTART": "1"})
    check("a driver on which dEQP cannot start is one clear error",
          r.rc == 1 and "does not start" in r.output, r.output)
    r = Run().run("--shard", "3/2")
    check("a bad shard is refused", r.rc == 2, r.output)


def test_shards_and_merge():
    whole = Run().run()
    outs = []
    for i in (1, 2, 3):
        r = Run()
        r.out = whole.out
        r.run("--shard", f"{i}/3")
        outs.append(os.path.join(whole.out, f"llvmpipe-gles2-all-s{i}of3"))
    seen = []
    for o in outs:
        with open(os.path.join(o, "summary.json")) as f:
            seen += list(json.load(f)["tests"])
    check("three shards cover every case exactly once",
          sorted(seen) == sorted(whole.summary()["tests"]), seen)
    p = subprocess.run([sys.executable, RUNNER, "--merge", *outs], stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True)
    check("the merge reports the whole run's counts",
          "deqp-gles2-llvmpipe: 9 passed, 1 failed, 2 skipped" in p.stdout, p.stdout)
    p = subprocess.run([sys.executable, RUNNER, "--merge", *outs[:2]], stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True)
    check("a merge with a shard missing fails and names it",
          p.returncode == 1 and "shards [3] of 3 are missing" in p.stdout, p.stdout)


def test_gitlab_shards_and_fixpipe_merge():
    whole = Run().run()
    out = os.path.join(whole.tmp.name, "sharded")
    rcs = []
    for i in (1, 2, 3):
        r = Run()
        r.out = out
        r.run(env={"CI_NODE_INDEX": str(i), "CI_NODE_TOTAL": "3"})
        rcs.append(r.rc)
    p = subprocess.run([os.path.join(REPO, "fixpipe"), "merge", out], stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True)
    path = os.path.join(out, "llvmpipe-gles2-all", "summary.json")
    merged = json.load(open(path)) if os.path.exists(path) else {"tests": {}}
    res = lambda s: {c: (t["result"], t["status"]) for c, t in s["tests"].items()}
    check("CI_NODE_INDEX/CI_NODE_TOTAL shards, ./fixpipe merge: the whole run's results, "
          "verdict and exit status", res(merged) == res(whole.summary())
          and merged.get("expected") == whole.summary()["expected"]
          and p.returncode == whole.rc, p.stdout + repr(rcs))


def test_lists():
    r = Run().run("--fraction", "4")
    s = r.summary("llvmpipe-gles2-all-f4")
    check("--fraction 4 runs every fourth case", s["total"] == 3, s["total"])
    lst = os.path.join(r.tmp.name, "mine.txt")
    with open(lst, "w") as f:
        f.write(f"{G}.a.*\n# a comment\n{G}.e.warn_1\n")
    r.run("--list", lst)
    s = r.summary("llvmpipe-gles2-mine")
    check("a list file takes names and globs", sorted(s["tests"]) == sorted(
        [f"{G}.a.pass_1", f"{G}.a.pass_2", f"{G}.e.warn_1"]), sorted(s["tests"]))
    with open(lst, "w") as f:
        f.write(f"{G}.no.such_case\n")
    r.run("--list", lst)
    check("a list naming no real case is refused", r.rc == 2 and "not dEQP-GLES2 cases"
          in r.output, r.output)


def test_sweep():
    r = Run()
    lst = os.path.join(r.tmp.name, "sweep.txt")
    with open(lst, "w") as f:
        f.write(f"{G}.a.*\n{G}.b.*\n{G}.e.*\n")
    out = os.path.join(r.tmp.name, "sweep")
    e = dict(os.environ, DEQP_BUILD=r.build, FAKE_DEQP_CASES=r.cases)
    # Debian's python3 has matplotlib (./fixpipe setup), the charts' one way
    p = subprocess.run(["/usr/bin/python3", RUNNER, "gles2", "--sweep", "--grid", "quick", "--list",
                        lst, "--out", out, "--launcher",
                        os.path.join(HERE, "fake-launcher")], env=e, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True, timeout=120)
    ok = p.returncode == 0 and os.path.exists(os.path.join(out, "sweep.json"))
    check("a quick sweep writes its table, chart and data", ok and all(
        os.path.exists(os.path.join(out, f)) for f in ("sweep.md", "sweep.png")), p.stdout)
    if ok:
        with open(os.path.join(out, "sweep.json")) as f:
            d = json.load(f)
        check("the sweep counts each group under each setting",
              [s["label"] for s in d["settings"]] == ["seed", "xy=12.4"]
              and d["groups"]["functional.fake.b"]["seed"] == [1, 2]
              and d["groups"]["functional.fake.a"]["xy=12.4"] == [2, 2]
              and d["groups"]["functional.fake.e"]["seed"] == [1, 1], d["groups"])


if __name__ == "__main__":
    sys.exit(T.run_tests(globals(), "harness-deqp"))
