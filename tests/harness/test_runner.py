#!/usr/bin/env python3
"""Tests of the piglit runner (piglit-lists/run.py, `./fixpipe piglit`) with a fake piglit.

Each case runs the real runner on a tiny list in a temporary directory; tests/harness/fake-piglit
decides each result from the test's name. Ends with 'harness: N passed, N failed'.
"""
import json
import os
import re
import subprocess
import sys
import tempfile

from tally import Tally

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
RUNNER = os.path.join(REPO, "piglit-lists", "run.py")
FAKE = os.path.join(HERE, "fake-piglit")

T = Tally(indent="  ")
check = T.check


class Case:
    """A temporary list + expectations, run through the runner."""

    def __init__(self, names, fails="", skips="", flakes="", header=""):
        self.tmp = tempfile.TemporaryDirectory(prefix="fixpipe-harness-")
        d = self.tmp.name
        self.list = os.path.join(d, "tiny.txt")
        with open(self.list, "w") as f:
            f.write(header + "".join(n + "\n" for n in names))
        self.exp = os.path.join(d, "exp")
        os.makedirs(self.exp)
        for kind, text in (("fails", fails), ("skips", skips), ("flakes", flakes)):
            with open(os.path.join(self.exp, f"llvmpipe-{kind}.txt"), "w") as f:
                f.write(text)
        self.out = os.path.join(d, "out")

    def run(self, *extra, via_launcher=False, piglit_dir=None):
        env = dict(os.environ, FIXPIPE_PIGLIT=FAKE, FIXPIPE_PIGLIT_DIR=piglit_dir or os.path.join(
            self.tmp.name, "no-piglit"), FIXPIPE_PIGLIT_OUT=self.out,
            FIXPIPE_PIGLIT_EXPECTATIONS=self.exp)
        env.pop("DISPLAY", None)
        if via_launcher:
            cmd = [os.path.join(REPO, "fixpipe"), "piglit", self.list, "--driver", "llvmpipe"]
        else:
            cmd = [sys.executable, RUNNER, self.list, "--driver", "llvmpipe"]
        p = subprocess.run(cmd + list(extra), env=env, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, text=True, timeout=120)
        self.rc, self.output = p.returncode, p.stdout
        return self

    def summary(self, sub="llvmpipe-tiny"):
        with open(os.path.join(self.out, sub, "summary.json")) as f:
            return json.load(f)

    def received(self, sub="llvmpipe-tiny"):
        path = os.path.join(self.out, sub, "surfaceless", "received.txt")
        return open(path).read().split("\n")[:-1] if os.path.exists(path) else []


BASE = ["fake@a@pass-1", "fake@a@pass-2", "fake@b@fail-known", "fake@c@skip-nogl",
        "fake@c@timeout-known", "fake@d@slow-excluded", "fake@d@fail-flaky"]
FAILS = """# reason: planted failure
fake@b@fail-known,Fail
# hangs in the fake
fake@c@timeout-known,Timeout
# the fake lacks the feature
fake@c@skip-nogl,Skip
"""
SKIPS = "# too slow\nslow-excluded$\n"
FLAKES = "# random\nflaky$\n"


def test_expected_results_exit_zero():
    c = Case(BASE, FAILS, SKIPS, FLAKES).run()
    check("listed failures and skips only: exit 0", c.rc == 0, c.output)
    check("the tally line counts the passes alone",
          "piglit-tiny-llvmpipe: 2 passed, 0 failed" in c.output, c.output)
    check("listed failures, skips, flakes and excluded tests are counted apart",
          "2 listed failures, 1 listed skips, 1 flakes, 1 not run" in c.output, c.output)
    check("an excluded test is not given to piglit",
          "fake@d@slow-excluded" not in c.received()
          and len(c.received()) == len(BASE) - 1, repr(c.received()))
    s = c.summary()
    t = s["tests"]
    check("summary: documented fields",
          all(k in s for k in ("format", "list", "driver", "profile", "shard", "started",
                               "seconds", "jobs", "total", "counts", "expected", "tests",
                               "exit_status")) and s["format"] == "fixpipe-piglit-summary/1",
          json.dumps(s, indent=1)[:800])
    check("summary: statuses",
          (t["fake@a@pass-1"]["status"], t["fake@b@fail-known"]["status"],
           t["fake@c@skip-nogl"]["status"], t["fake@d@slow-excluded"]["status"],
           t["fake@d@fail-flaky"]["status"], t["fake@c@timeout-known"]["status"])
          == ("ok", "expected", "skipped", "excluded", "flake", "expected"),
          json.dumps(t, indent=1))
    check("summary: reason of a listed failure",
          t["fake@b@fail-known"].get("reason") == "reason: planted failure", repr(t))
    check("summary: counts",
          s["counts"] == {"pass": 2, "warn": 0, "fail": 2, "crash": 0, "timeout": 1,
                          "skip": 1, "notrun": 0, "excluded": 1} and s["total"] == 7,
          repr(s["counts"]))


def test_new_failure_exits_nonzero():
    for planted, word in (("fake@e@fail-new", "FAIL"), ("fake@e@crash-new", "CRASH"),
                          ("fake@e@vanish-new", "NOTRUN"), ("fake@e@timeout-new", "TIMEOUT")):
        c = Case(BASE + [planted], FAILS, SKIPS, FLAKES).run()
        check(f"a new {word.lower()} exits 1 and is listed",
              c.rc == 1 and f"{word:<12} {planted} (expected pass)" in c.output
              and c.summary()["tests"][planted]["status"] == "unexpected"
              and c.summary()["exit_status"] == 1, c.output)


def test_expected_crash_differs_from_fail():
    c = Case(["fake@f@fail-x"], "# r\nfake@f@fail-x,Crash\n").run()
    check("a failure listed as Crash is a difference", c.rc == 1, c.output)


def test_new_skip():
    c = Case(["fake@a@pass-1", "fake@c@skip-nogl"]).run()
    check("a run-time skip not listed exits 1 (a feature no longer exposed)",
          c.rc == 1 and "SKIP         fake@c@skip-nogl (expected pass)" in c.output
          and c.summary()["tests"]["fake@c@skip-nogl"]["status"] == "unexpected", c.output)


def test_unexpected_pass():
    for line in ("fake@b@pass-was-failing,Fail", "fake@b@pass-was-failing,Skip"):
        c = Case(["fake@a@pass-1", "fake@b@pass-was-failing"], f"# fixed since\n{line}\n").run()
        check(f"a pass listed as {line.split(',')[1]} exits 1 until its line goes",
              c.rc == 1 and "UnexpectedPass fake@b@pass-was-failing" in c.output
              and "remove its line" in c.output
              and c.summary()["tests"]["fake@b@pass-was-failing"]["status"] == "unexpected_pass",
              c.output)


def test_grouped_reasons():
    c = Case(["fake@g@skip-a", "fake@g@skip-b", "fake@g@fail-c"],
             "# the fake lacks the feature\nfake@g@skip-a,Skip\nfake@g@skip-b,Skip\n"
             "# a planted failure\nfake@g@fail-c,Fail\n").run()
    t = c.summary()["tests"] if c.rc == 0 else {}
    check("a comment is the reason of the run of entries below it",
          c.rc == 0 and t["fake@g@skip-b"].get("reason") == "the fake lacks the feature"
          and t["fake@g@fail-c"].get("reason") == "a planted failure", c.output)


def test_bad_expectations():
    c = Case(["fake@a@pass-1"], "# r\nfake@a@pass-1,Bogus\n").run()
    check("a malformed fails line is refused", c.rc == 2 and "Fail|Crash|Timeout|Skip"
          in c.output, c.output)


def test_usage_errors():
    c = Case(["fake@a@pass-1"])
    check("unknown driver: exit 2", c.run("--driver", "nopipe").rc == 2, c.output)
    check("bad shard: exit 2", c.run("--shard", "5/4").rc == 2, c.output)
    check("bad shard syntax: exit 2", c.run("--shard", "x").rc == 2, c.output)


def test_sharding():
    names = [f"fake@s{k % 5}@pass-{k:02d}" for k in range(23)] + ["fake@s@slow-excluded"]
    c = Case(names, skips=SKIPS)
    n = 4
    seen, sizes = [], []
    for i in range(1, n + 1):
        c.run("--shard", f"{i}/{n}")
        s = c.summary(f"llvmpipe-tiny-s{i}of{n}")
        seen += list(s["tests"])
        sizes.append(len(s["tests"]))
        check(f"shard {i}/{n} exits 0 and says which it is",
              c.rc == 0 and s["shard"] == [i, n], c.output)
    check("the shards cover the list exactly once",
          sorted(seen) == sorted(names) and len(seen) == len(set(seen)), repr(sorted(seen)))
    check("shard sizes differ by at most one", max(sizes) - min(sizes) <= 1, repr(sizes))
    c.run("--shard", f"2/{n}")
    again = sorted(c.summary(f"llvmpipe-tiny-s2of{n}")["tests"])
    c.run("--shard", f"2/{n}")
    check("a shard is the same on every run",
          again == sorted(c.summary(f"llvmpipe-tiny-s2of{n}")["tests"]))
    dirs = [os.path.join(c.out, f"llvmpipe-tiny-s{i}of{n}") for i in range(1, n + 1)]
    p = subprocess.run([sys.executable, RUNNER, "--merge"] + dirs, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True)
    check("--merge of all shards: exit 0, whole-list tally",
          p.returncode == 0 and "piglit-tiny-llvmpipe: 23 passed, 0 failed" in p.stdout,
          p.stdout)
    p = subprocess.run([sys.executable, RUNNER, "--merge"] + dirs[:-1], stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True)
    check("--merge with a shard missing: exit 1", p.returncode == 1, p.stdout)


def test_concurrent_runs():
    c = Case(BASE, FAILS, SKIPS, FLAKES)
    env = dict(os.environ, FIXPIPE_PIGLIT=FAKE, FIXPIPE_PIGLIT_DIR=os.path.join(
        c.tmp.name, "no-piglit"), FIXPIPE_PIGLIT_OUT=c.out, FIXPIPE_PIGLIT_EXPECTATIONS=c.exp,
        FAKE_PIGLIT_DELAY="1")
    env.pop("DISPLAY", None)
    cmd = [sys.executable, RUNNER, c.list, "--driver", "llvmpipe"]
    procs = [subprocess.Popen(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              text=True) for _ in range(2)]
    outs = [p.communicate(timeout=120)[0] for p in procs]
    check("two runs of one list at once: both complete and agree",
          all(p.returncode == 0 for p in procs)
          and sum("waiting for another run" in o for o in outs) == 1, "\n".join(outs))


def test_launcher():
    c = Case(BASE + ["fake@e@fail-new"], FAILS, SKIPS, FLAKES).run(via_launcher=True)
    check("./fixpipe piglit: a new failure exits 1",
          c.rc == 1 and "FAIL         fake@e@fail-new" in c.output, c.output)
    c = Case(BASE, FAILS, SKIPS, FLAKES).run(via_launcher=True)
    check("./fixpipe piglit: expected results exit 0", c.rc == 0, c.output)


PIGLIT = "/usr/lib/x86_64-linux-gnu/piglit"


def test_profile_of_the_list():
    """piglit gets a profile of the list's tests alone, copied from its own profiles, and its
    own loader reads that profile back as the same tests with the same options."""
    import gzip
    c = Case(["fake@p@pass-in-gl", "fake@p@pass-not-in-piglit", "fake@p@pass-in-shader"])
    d = os.path.join(c.tmp.name, "piglit")
    os.makedirs(os.path.join(d, "tests"))
    gl = ('<PiglitTestList count="3" name="quick_gl">'
          '<Test type="gl" name="fake@p@pass-in-gl"><option name="command" value="[\'a\', \'-fbo\']" />'
          '<option name="run_concurrent" value="True" /></Test>'
          '<Test type="gl" name="fake@p@pass-other"><option name="command" value="[\'b\']" />'
          '<option name="run_concurrent" value="True" /></Test></PiglitTestList>')
    sh = ('<PiglitTestList count="1" name="quick_shader">'
          '<Test type="gl" name="fake@p@pass-in-shader"><option name="command" value="[\'c\']" />'
          '<option name="run_concurrent" value="True" /></Test></PiglitTestList>')
    for name, text in (("quick_gl", gl), ("quick_shader", sh)):
        with gzip.open(os.path.join(d, "tests", name + ".xml.gz"), "wt") as f:
            f.write(text)
    c.run(piglit_dir=d)
    got = os.path.join(c.out, "llvmpipe-tiny", "surfaceless", "profile.txt")
    names = open(got).read().split() if os.path.exists(got) else None
    check("the profile holds the list's tests that piglit has, nothing else",
          names == ["fake@p@pass-in-gl", "fake@p@pass-in-shader"], f"{names}\n{c.output}")
    profile = os.path.join(c.out, "llvmpipe-tiny", "surfaceless.profile.xml.gz")
    sys.path.insert(0, PIGLIT)
    try:
        from framework import profile as piglit_profile
        loaded = piglit_profile.load_test_profile(profile)
        tests = dict(loaded.itertests())
        check("piglit's loader reads it, with each test's command",
              sorted(tests) == ["fake@p@pass-in-gl", "fake@p@pass-in-shader"]
              and tests["fake@p@pass-in-gl"].command[0].endswith("/bin/a")
              and "-fbo" in tests["fake@p@pass-in-gl"].command,
              f"{type(loaded).__name__} {sorted(tests)} {tests['fake@p@pass-in-gl'].command}")
    finally:
        sys.path.remove(PIGLIT)


def test_checked_in_expectations():
    """Every line of the drivers' fails.txt has a reason; fixpipe's names no
    known bug (a BUG line is work to do, not an expected result)."""
    exp = os.path.join(REPO, "piglit-lists", "expectations")
    for driver in ("fixpipe", "softpipe", "llvmpipe"):
        lines = open(os.path.join(exp, f"{driver}-fails.txt")).read().split("\n")
        unexplained, reason = [], False
        for line in lines:
            if line.startswith("#"):
                reason = True
            elif line.strip():
                if not reason:
                    unexplained.append(line)
            else:
                reason = False
        check(f"{driver}-fails.txt: every entry under a reason", not unexplained,
              "\n".join(unexplained[:5]))
        if driver == "fixpipe":
            bugs = [l for l in lines if re.search(r"\bBUG\b", l)]
            check("fixpipe-fails.txt: no BUG line", not bugs, "\n".join(bugs))


if __name__ == "__main__":
    sys.exit(T.run_tests(globals(), "harness"))
