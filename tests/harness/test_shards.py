#!/usr/bin/env python3
"""Tests of campaign shards and `./fixpipe merge` (docs/cluster.md), without a cluster: the
piglit runner with the fake piglit, shards taken from GitLab's and Slurm's variables, the
merge against the whole run, and the refusals (a missing or unfinished shard, two campaigns
in one directory, shards into a merged run, --slurm without sbatch).  A few seconds; ends
with 'harness-shards: N passed, N failed'.
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

from tally import Tally

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
RUNNER = os.path.join(REPO, "piglit-lists", "run.py")
LAUNCHER = os.path.join(REPO, "fixpipe")
FAKE = os.path.join(HERE, "fake-piglit")

T = Tally(indent="  ")
check = T.check

# 17 tests: passes, an expected failure, a new failure, an excluded one
NAMES = [f"fake@g{k % 4}@pass-{k:02d}" for k in range(14)] + \
    ["fake@b@fail-known", "fake@b@fail-new", "fake@d@slow-excluded"]
FAILS = "# reason: planted failure\nfake@b@fail-known,Fail\n"
SKIPS = "# too slow\nslow-excluded$\n"
SHARD_VARS = ("SLURM_ARRAY_TASK_ID", "SLURM_ARRAY_TASK_MIN", "SLURM_ARRAY_TASK_STEP",
              "SLURM_ARRAY_TASK_COUNT", "SLURM_ARRAY_JOB_ID", "SLURM_JOB_ID", "CI_NODE_INDEX",
              "CI_NODE_TOTAL")


class Setup:
    def __init__(self):
        self.tmp = tempfile.TemporaryDirectory(prefix="fixpipe-shards-")
        d = self.tmp.name
        self.list = os.path.join(d, "tiny.txt")
        with open(self.list, "w") as f:
            f.write("".join(n + "\n" for n in NAMES))
        self.other = os.path.join(d, "other.txt")
        with open(self.other, "w") as f:
            f.write("fake@x@pass-1\n")
        self.exp = os.path.join(d, "exp")
        os.makedirs(self.exp)
        for kind, text in (("fails", FAILS), ("skips", SKIPS), ("flakes", "")):
            with open(os.path.join(self.exp, f"llvmpipe-{kind}.txt"), "w") as f:
                f.write(text)

    def dir(self, name):
        return os.path.join(self.tmp.name, name)

    def piglit(self, out, *extra, env=None, lst=None):
        e = {k: v for k, v in os.environ.items() if k not in SHARD_VARS and k != "DISPLAY"}
        e.update(FIXPIPE_PIGLIT=FAKE, FIXPIPE_PIGLIT_DIR=self.dir("no-piglit"),
                 FIXPIPE_PIGLIT_EXPECTATIONS=self.exp)
        e.update(env or {})
        cmd = [sys.executable, RUNNER, lst or self.list, "--driver", "llvmpipe"] + \
            (["--out", out] if out else []) + list(extra)
        if not out:
            e["FIXPIPE_PIGLIT_OUT"] = self.dir("default-out")
        return subprocess.run(cmd, env=e, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              text=True, timeout=120)


def merge(d, *extra):
    return subprocess.run([LAUNCHER, "merge", d] + list(extra), stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True, timeout=300)


def summary(path):
    with open(os.path.join(path, "summary.json")) as f:
        return json.load(f)


def per_test(s):
    return {n: (t["result"], t["status"]) for n, t in s["tests"].items()}


S = Setup()


def test_gitlab_variables_cover_the_list_once():
    n = 3
    out = S.dir("gitlab")
    seen, rcs = [], []
    for i in range(1, n + 1):
        p = S.piglit(out, env={"CI_NODE_INDEX": str(i), "CI_NODE_TOTAL": str(n)})
        rcs.append(p.returncode)
        s = summary(os.path.join(out, f"llvmpipe-tiny-s{i}of{n}"))
        seen += list(s["tests"])
        with open(os.path.join(out, f"llvmpipe-tiny-s{i}of{n}", "shard.json")) as f:
            mark = json.load(f)
        check(f"CI_NODE_INDEX={i} CI_NODE_TOTAL={n}: shard {i}/{n}, marked complete",
              s["shard"] == [i, n] and mark["shard"] == [i, n] and mark["campaign"] == "piglit",
              p.stdout)
    check(f"the {n} shards cover the list exactly once",
          sorted(seen) == sorted(NAMES) and len(seen) == len(set(seen)), repr(sorted(seen)))
    whole = S.piglit(S.dir("whole"))
    m = merge(out)
    merged = summary(os.path.join(out, "llvmpipe-tiny"))
    ref = summary(os.path.join(S.dir("whole"), "llvmpipe-tiny"))
    check("./fixpipe merge: the whole run's per-test results, counts and exit status",
          per_test(merged) == per_test(ref) and merged["counts"] == ref["counts"]
          and merged["expected"] == ref["expected"] and m.returncode == whole.returncode == 1
          and merged["exit_status"] == 1, m.stdout + "\n" + repr(rcs))
    check("the merge prints the whole run's verdict line",
          "piglit-tiny-llvmpipe: 14 passed, 1 failed" in m.stdout
          and "piglit-tiny-llvmpipe: 14 passed, 1 failed" in whole.stdout, m.stdout)
    p = S.piglit(out, "--shard", "1/3")
    check("shards into a merged run are refused", p.returncode == 2
          and "complete merged run" in p.stdout, p.stdout)


def test_slurm_variables():
    out = S.dir("slurm")
    names = []
    for tid in (0, 1, 2):  # an array 0-2: the shards are 1..3
        S.piglit(out, env={"SLURM_ARRAY_TASK_ID": str(tid), "SLURM_ARRAY_TASK_MIN": "0",
                           "SLURM_ARRAY_TASK_COUNT": "3", "SLURM_ARRAY_JOB_ID": "77"})
        names.append(sorted(os.path.basename(d) for d in os.listdir(out)
                            if d.startswith("llvmpipe-tiny-s") and not d.endswith(".lock")))
    check("SLURM_ARRAY_TASK_ID 0..2 of an array from 0: shards 1/3, 2/3, 3/3",
          names[-1] == ["llvmpipe-tiny-s1of3", "llvmpipe-tiny-s2of3", "llvmpipe-tiny-s3of3"],
          repr(names))
    p = S.piglit(S.dir("override"), "--shard", "2/2",
                 env={"CI_NODE_INDEX": "1", "CI_NODE_TOTAL": "5"})
    check("--shard wins over the variables",
          os.path.isdir(os.path.join(S.dir("override"), "llvmpipe-tiny-s2of2")), p.stdout)
    p = S.piglit(S.dir("bad"), env={"CI_NODE_INDEX": "0", "CI_NODE_TOTAL": "2"})
    check("CI_NODE_INDEX=0 (GitLab counts from 1): exit 2, says so",
          p.returncode == 2 and "CI_NODE_INDEX/CI_NODE_TOTAL" in p.stdout, p.stdout)


def test_incomplete_merges_fail_and_name_the_shard():
    out = S.dir("incomplete")
    for i in (1, 3):
        S.piglit(out, "--shard", f"{i}/3")
    m = merge(out)
    check("a shard never run: the merge exits 1, names it, writes nothing",
          m.returncode == 1 and "shard 2/3: never started" in m.stdout
          and not os.path.exists(os.path.join(out, "llvmpipe-tiny"))
          and " passed, 0 failed" not in m.stdout.replace("merge: 0 passed, 1 failed", ""),
          m.stdout)
    S.piglit(out, "--shard", "2/3")
    os.remove(os.path.join(out, "llvmpipe-tiny-s2of3", "shard.json"))  # as if killed
    m = merge(out)
    check("a shard started and never finished: named, with its host",
          m.returncode == 1 and "shard 2/3: started on" in m.stdout
          and "no results" in m.stdout, m.stdout)
    S.piglit(out, "--shard", "2/3")
    m = merge(out)
    check("once shard 2 has run again, the merge passes on",
          m.returncode == 1 and "every shard complete" in m.stdout
          and os.path.exists(os.path.join(out, "llvmpipe-tiny", "summary.json")), m.stdout)


def test_two_campaigns_in_one_directory():
    out = S.dir("two")
    S.piglit(out, "--shard", "1/2")
    p = S.piglit(out, "--shard", "1/2", lst=S.other)
    check("a second campaign into the same --out: exit 2, says whose the directory is",
          p.returncode == 2 and "holds another campaign" in p.stdout, p.stdout)
    p = S.piglit(out, "--shard", "1/3")
    check("the same list split another way into it: refused as well", p.returncode == 2,
          p.stdout)
    # shards written without --out land in the default place, each its own
    d = S.dir("default-out")
    S.piglit(None, "--shard", "1/2")
    S.piglit(None, "--shard", "1/2", lst=S.other)
    m = merge(d)
    check("a merge over shards of two campaigns: exit 2, names both",
          m.returncode == 2 and "more than one campaign" in m.stdout, m.stdout)


def test_slurm_without_sbatch():
    env = dict(os.environ, PATH=S.dir("empty-path"))
    p = subprocess.run(["/usr/bin/python3", os.path.join(REPO, "tools", "fp-cluster"), "submit",
                        "piglit", S.list, "--slurm"], env=env, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True)
    check("--slurm with no sbatch on the PATH: exit 2, says what is missing and the way "
          "without a cluster", p.returncode == 2 and "sbatch" in p.stdout
          and "--shard I/N" in p.stdout, p.stdout)
    p = subprocess.run([LAUNCHER, "piglit", S.list, "--slurm", "--shard", "1/2"],
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    check("--slurm with --shard: refused", p.returncode == 2 and "no --shard" in p.stdout,
          p.stdout)


def test_stress_shards():
    if not os.path.exists(os.path.join(REPO, "build", "std", "tests", "unit", "test_scan_ref")):
        check("stress shards (build/std is not built)", False)
        return
    out = S.dir("stress")
    for i in (1, 2):
        subprocess.run([LAUNCHER, "stress", "4000", "--jobs", "2", "--shard", f"{i}/2",
                        "--out", out], stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    m = merge(out)
    parts = [json.load(open(os.path.join(out, f"stress-s{i}of2", "shard.json")))["totals"]
             for i in (1, 2)]
    tri = sum(p["triangles"] for p in parts)
    check("stress: two shards merge into the totals of both, seeds 1..4",
          m.returncode == 0 and f"PASS stress: {tri} triangles" in m.stdout and tri >= 4000
          and "seeds 1..4" in m.stdout, m.stdout)


if __name__ == "__main__":
    try:
        sys.exit(T.run_tests(globals(), "harness-shards"))
    finally:
        shutil.rmtree(S.tmp.name, ignore_errors=True)
