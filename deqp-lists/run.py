#!/usr/bin/env python3
"""Runs the Khronos dEQP suite (GL ES 2.0 / 3.0) on one driver against its expectations.

usage: run.py gles2|gles3 [--list mustpass|all|FILE] [--driver D] [--shard I/N]
              [--fraction N] [--jobs J] [--timeout S] [--chunk N] [--out DIR]
       run.py gles2|gles3 --sweep [--grid full|quick] [--list FILE]   (sweep.py)
       run.py --merge DIR...     combine the summary.json files of the shards of one run

In the spirit of Mesa CI's deqp-runner: the case list is cut into chunks, each run by one
dEQP process through `./fixpipe run`; a case that crashes the process or hangs past the
timeout is recorded as Crash or Timeout and the chunk goes on in a new process after it.
A new failure is run again alone in a fresh process: if it then passes it is a Flake
(reported, not fatal).  Results: results.csv (one line a case), the QPA log of every case
that did not pass under qpa/, summary.json.  docs/deqp.md describes it all.
"""
import argparse
import concurrent.futures
import csv
import datetime
import fcntl
import fnmatch
import json
import os
import re
import select
import shutil
import signal
import subprocess
import sys
import tarfile
import tempfile
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(REPO, "tools"))
from fpexpect import (bad_input, finish_merge, join_shards, matching, parse_shard, read_fails,  # noqa: E402
                      read_regexes, shard)
import fpshard  # noqa: E402

DRIVERS = ("fixpipe", "softpipe", "llvmpipe")
MODULES = {"gles2": "dEQP-GLES2", "gles3": "dEQP-GLES3"}
FORMAT = "fixpipe-deqp-summary/1"
# dEQP's status codes (qpTestResult) and how the runner counts them
STATUS = {
    "Pass": "pass", "Fail": "fail", "QualityWarning": "warn", "CompatibilityWarning": "warn",
    "NotSupported": "notsupported", "ResourceError": "fail", "InternalError": "fail",
    "Crash": "crash", "Timeout": "timeout", "Waiver": "fail",
}
COUNT_KEYS = ("pass", "warn", "fail", "crash", "timeout", "notsupported", "flake", "excluded")
# Timing benchmarks, not conformance (and not in the Khronos must-pass lists)
NOT_CONFORMANCE = re.compile(r"\.(performance|stress)\.")
DEQP_ARGS = [
    "--deqp-surface-type=pbuffer", "--deqp-gl-config-name=rgba8888d24s8ms0",
    "--deqp-surface-width=256", "--deqp-surface-height=256", "--deqp-visibility=hidden",
    "--deqp-log-flush=enable", "--deqp-watchdog=disable", "--deqp-log-images=disable",
    "--deqp-log-shader-sources=disable",
]


# ------------------------------------------------------------------ finding dEQP
def deqp_build(work):
    """The directory holding modules/gles2/deqp-gles2: DEQP_BUILD, or the shared tarball
    unpacked once into WORK/deqp."""
    if os.environ.get("DEQP_BUILD"):
        d = os.environ["DEQP_BUILD"]
        if not os.path.exists(os.path.join(d, "modules", "gles2", "deqp-gles2")):
            bad_input(f"DEQP_BUILD={d} has no modules/gles2/deqp-gles2 (docs/deqp.md)")
        return d
    d = os.path.join(work, "deqp")
    if os.path.exists(os.path.join(d, ".unpacked")):
        return d
    tarball = os.path.join(os.path.dirname(REPO), "shared", "deqp", "deqp-build.tar.xz")
    if not os.path.exists(tarball):
        bad_input("no dEQP: set DEQP_BUILD to a dEQP build directory, or put deqp-build.tar.xz "
                  f"in {os.path.dirname(tarball)} (docs/deqp.md says how to build one)")
    os.makedirs(work, exist_ok=True)
    with open(os.path.join(work, "deqp.lock"), "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not os.path.exists(os.path.join(d, ".unpacked")):
            tmp = tempfile.mkdtemp(dir=work, prefix="deqp-unpack.")
            with tarfile.open(tarball) as t:
                t.extractall(tmp)
            shutil.rmtree(d, ignore_errors=True)
            os.rename(tmp, d)
            open(os.path.join(d, ".unpacked"), "w").close()
    return d


def module_paths(build, module):
    mdir = os.path.join(build, "modules", module)
    return os.path.join(mdir, "deqp-" + module), mdir


def full_caselist(args, build, module):
    """Every case of the module (dEQP's txt-caselist), cached next to the build."""
    binary, mdir = module_paths(build, module)
    cache = os.path.join(build, f"{MODULES[module]}-cases.txt")
    if not os.path.exists(cache) or os.path.getmtime(cache) < os.path.getmtime(binary):
        with tempfile.TemporaryDirectory() as tmp:
            cmd = [args.launcher, "run", "--driver", "llvmpipe", "--no-xvfb", "--", binary,
                   "--deqp-runmode=txt-caselist", "--deqp-surface-type=pbuffer",
                   f"--deqp-archive-dir={mdir}"]
            p = subprocess.run(cmd, cwd=tmp, capture_output=True, text=True)
            out = os.path.join(tmp, f"{MODULES[module]}-cases.txt")
            if p.returncode != 0 or not os.path.exists(out):
                bad_input(f"{binary} could not list its cases:\n{p.stdout[-2000:]}{p.stderr[-2000:]}")
            shutil.copy(out, cache + ".tmp")
            os.replace(cache + ".tmp", cache)
    with open(cache, encoding="utf-8") as f:
        return [ln[6:].strip() for ln in f if ln.startswith("TEST: ")]


def read_patterns(path):
    """Case names or dEQP globs ('*'), '#' comments and blank lines ignored."""
    out = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            s = line.split("#")[0].strip()
            if s:
                out.append(s)
    return out


def select_cases(args, build):
    cases = [c for c in full_caselist(args, build, args.module) if not NOT_CONFORMANCE.search(c)]
    if args.list == "all":
        return cases
    if args.list == "mustpass":
        path = os.path.join(HERE, "mustpass", f"{args.module}-exclude.txt")
        globs = [p for p in read_patterns(path) if "*" in p]
        names = {p for p in read_patterns(path) if "*" not in p}
        rx = re.compile("|".join(fnmatch.translate(g) for g in globs)) if globs else None
        return [c for c in cases if c not in names and not (rx and rx.match(c))]
    if not os.path.exists(args.list):
        bad_input(f"no case list {args.list} (accepted: mustpass, all, or a file of case names)")
    wanted = read_patterns(args.list)
    known = set(cases)
    globs = [w for w in wanted if "*" in w]
    unknown = [w for w in wanted if "*" not in w and w not in known]
    if unknown:
        bad_input(f"{args.list}: {len(unknown)} names are not {MODULES[args.module]} cases, "
                  f"e.g. {unknown[0]}")
    rx = re.compile("|".join(fnmatch.translate(g) for g in globs)) if globs else None
    plain = set(wanted)
    return [c for c in cases if c in plain or (rx and rx.match(c))]


# ------------------------------------------------------------------ running
CASE_RE = re.compile(r"^Test case '([^']+)'\.\.")
STATUS_RE = re.compile(r"^  (\w+) \((.*)\)\s*$")


class Chunk:
    """Runs a list of cases in as many dEQP processes as crashes and hangs need."""

    def __init__(self, args, build, cases, workdir, tag):
        self.args, self.build, self.cases = args, build, cases
        self.workdir, self.tag = workdir, tag
        self.results = {}          # name -> (status, seconds, detail)
        self.qpas = []

    def run(self):
        todo = list(self.cases)
        attempt = 0
        while todo:
            attempt += 1
            if not self._process(todo, attempt):
                # the process ended or hung before it started a case: the driver cannot start
                raise RuntimeError(f"{self.tag}.{attempt}: dEQP started no case")
            todo = [c for c in todo if c not in self.results]
        return self

    def _process(self, todo, attempt):
        binary, mdir = module_paths(self.build, self.args.module)
        listfile = os.path.join(self.workdir, f"{self.tag}.{attempt}.txt")
        qpa = os.path.join(self.workdir, f"{self.tag}.{attempt}.qpa")
        with open(listfile, "w", encoding="utf-8") as f:
            f.write("\n".join(todo) + "\n")
        cmd = [self.args.launcher, "run", "--driver", self.args.driver, "--no-xvfb", "--",
               "stdbuf", "-oL", binary, *DEQP_ARGS, f"--deqp-archive-dir={mdir}",
               f"--deqp-caselist-file={listfile}", f"--deqp-log-filename={qpa}"]
        p = subprocess.Popen(cmd, cwd=self.workdir, stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, start_new_session=True)
        self.qpas.append(qpa)
        current, started, tail, buf, started_any = None, 0.0, [], b"", False
        deadline = time.time() + self.args.timeout
        fd = p.stdout.fileno()
        while True:
            ready, _, _ = select.select([fd], [], [], max(0.0, deadline - time.time()))
            if not ready:
                # no case finished within the timeout: the current one hangs
                os.killpg(p.pid, signal.SIGKILL)
                p.wait()
                if current:
                    self._record(current, "Timeout", started, tail)
                return started_any
            data = os.read(fd, 65536)
            if not data:
                break
            buf += data
            *lines, buf = buf.split(b"\n")
            for raw in lines:
                line = raw.decode("utf-8", "replace")
                tail = (tail + [line])[-30:]
                m = CASE_RE.match(line)
                if m:
                    current, started, started_any = m.group(1), time.time(), True
                    deadline = started + self.args.timeout
                    tail = [line]
                    continue
                m = STATUS_RE.match(line)
                if m and current and m.group(1) in STATUS:
                    self.results[current] = (m.group(1), time.time() - started, m.group(2))
                    current = None
                    deadline = time.time() + self.args.timeout
        rc = p.wait()
        if current:
            # the process ended inside a case: it crashed there
            self._record(current, "Crash", started, tail + [f"exit status {rc}"])
        return started_any

    def _record(self, name, status, started, tail):
        self.results[name] = (status, time.time() - started, "")
        logdir = os.path.join(self.args.outdir, "logs")
        os.makedirs(logdir, exist_ok=True)
        with open(os.path.join(logdir, name + ".log"), "w", encoding="utf-8") as f:
            f.write("\n".join(tail) + "\n")


def qpa_sections(path, names):
    """The #beginTestCaseResult ... #endTestCaseResult text of the named cases in a QPA log."""
    out, cur, lines = {}, None, []
    try:
        f = open(path, encoding="utf-8", errors="replace")
    except FileNotFoundError:
        return out
    with f:
        for line in f:
            if line.startswith("#beginTestCaseResult "):
                cur = line.split(None, 1)[1].strip()
                lines = [line] if cur in names else None
            elif cur is not None and lines is not None:
                lines.append(line)
                if line.startswith("#endTestCaseResult") or line.startswith("#terminateTestCaseResult"):
                    out[cur] = "".join(lines)
                    cur = None
    return out


def run_cases(args, build, cases, workdir, tag):
    """{name: (dEQP status, seconds, detail)} for the cases, J processes at once."""
    n = max(1, min(args.chunk, -(-len(cases) // max(1, args.jobs))))
    # interleave so that each chunk gets a mix of groups (slow groups spread over the jobs)
    chunks = [cases[i::-(-len(cases) // n)] for i in range(-(-len(cases) // n))] if cases else []
    results, qpas = {}, []
    done, lock, t0 = [0], threading.Lock(), time.time()

    def one(k):
        c = Chunk(args, build, chunks[k], workdir, f"{tag}{k:04d}").run()
        with lock:
            done[0] += len(c.cases)
            if not args.quiet:
                print(f"  {done[0]}/{len(cases)} cases, {time.time() - t0:.0f} s", flush=True)
        return c

    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as ex:
        for c in ex.map(one, range(len(chunks))):
            results.update(c.results)
            qpas.extend(c.qpas)
    return results, qpas


# ------------------------------------------------------------------ comparing
def classify(name, deqp_status, fails, flakes):
    """(result, expected, status, reason): status is ok, expected, unexpected, unexpected_pass,
    flake (matched by the flakes file) or notsupported."""
    result = STATUS.get(deqp_status, "fail")
    reason = matching(flakes, name)
    if reason is not None:
        return result, "flake", "flake", reason
    expected, reason = fails.get(name, ("pass", ""))
    if result in ("pass", "warn"):
        return result, expected, "ok" if expected == "pass" else "unexpected_pass", reason
    if result == "notsupported":
        return result, expected, "notsupported", reason
    if result == expected:
        return result, expected, "expected", reason
    return result, expected, "unexpected", reason


def tally(tests):
    counts = dict.fromkeys(COUNT_KEYS, 0)
    expected = {"met": 0, "unexpected": 0, "unexpected_pass": 0, "skipped": 0}
    for t in tests.values():
        counts[t["result"]] += 1
        if t["status"] in ("unexpected", "unexpected_pass"):
            expected["unexpected"] += 1
            expected["unexpected_pass"] += t["status"] == "unexpected_pass"
        elif t["status"] in ("excluded", "notsupported"):
            # not run, or run and found the feature missing: neither is a pass
            expected["skipped"] += 1
        else:
            expected["met"] += 1
    return counts, expected


def report(summary, label, fails_file):
    for name, t in sorted(summary["tests"].items()):
        if t["status"] == "unexpected_pass":
            print(f"  UnexpectedPass {name} (expected {t['expected']}: remove its line from "
                  f"{fails_file})")
        elif t["status"] == "unexpected":
            print(f"  {t['result'].upper():<8} {name} (expected {t['expected']})")
        elif t["result"] == "flake":
            print(f"  Flake    {name} (failed, then passed alone)")
    c = summary["counts"]
    print(f"{label}: " + ", ".join(f"{c[k]} {k}" for k in COUNT_KEYS
                                   if c[k] or k in ("pass", "fail", "crash", "timeout")))
    e = summary["expected"]
    print(f"{label}: {e['met']} passed, {e['unexpected']} failed, {e['skipped']} skipped")
    return 1 if e["unexpected"] else 0


def cmd_run(args):
    build = deqp_build(args.work)
    cases = select_cases(args, build)
    if args.fraction > 1:
        cases = cases[::args.fraction]
    exp = args.expectations
    fails_file = os.path.join(exp, f"{args.driver}-fails.txt")
    fails = read_fails(fails_file, fold_case=False)
    skips = read_regexes(os.path.join(exp, f"{args.driver}-skips.txt"))
    flakes = read_regexes(os.path.join(exp, f"{args.driver}-flakes.txt"))
    si, sn, sharded = fpshard.resolve(args.shard)
    if sn > 1:
        cases = shard(cases, si, sn)
    excluded = {c: r for c in cases for r in [matching(skips, c)] if r is not None}
    to_run = [c for c in cases if c not in excluded]
    # a list file names the run by its base name (mustpass, all, or FILE's)
    label = os.path.basename(args.list)
    label = label[:-4] if label.endswith(".txt") else label
    name = f"{args.driver}-{args.module}-{label}" + (f"-f{args.fraction}" if args.fraction > 1 else "") \
        + (f"-s{si}of{sn}" if sharded else "")
    args.outdir = out_dir = os.path.join(args.out, name)
    os.makedirs(args.out, exist_ok=True)
    lock = open(out_dir + ".lock", "w")
    try:
        fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        print(f"fixpipe: another run writes {os.path.relpath(out_dir, REPO)}: waiting for it",
              flush=True)
        fcntl.flock(lock, fcntl.LOCK_EX)
    shutil.rmtree(out_dir, ignore_errors=True)
    work = os.path.join(out_dir, "work")
    os.makedirs(work)
    key = {"module": args.module, "list": label, "driver": args.driver,
           "fraction": args.fraction, "profile": os.environ.get("FIXPIPE_PROFILE") or "seed",
           "texfmt": os.environ.get("FIXPIPE_TEXFMT") or "dfx24"}
    if sharded:
        # a result directory named on the command line is one campaign's (docs/cluster.md)
        fpshard.claim(args.out if args.out_given else out_dir, out_dir, "deqp", key, si, sn)
    started = datetime.datetime.now(datetime.timezone.utc)
    t0 = time.time()
    print(f"fixpipe: {MODULES[args.module]} {label} on {args.driver}"
          + (f", every {args.fraction}th case" if args.fraction > 1 else "")
          + (f", shard {si}/{sn}" if sn > 1 else "")
          + f": {len(to_run)} cases, {len(excluded)} excluded, {args.jobs} jobs, "
          f"results in {os.path.relpath(out_dir, REPO)}", flush=True)
    try:
        raw, qpas = run_cases(args, build, to_run, work, "c")
    except RuntimeError:
        print(f"fixpipe: {MODULES[args.module]} does not start on {args.driver}; "
              f"its output is in {os.path.relpath(work, REPO)}", file=sys.stderr)
        return 1
    # a new failure is run again alone, in a fresh process: one that passes then is a flake
    again = [c for c in to_run if classify(c, raw[c][0], fails, flakes)[2] == "unexpected"
             and raw[c][0] not in ("Crash", "Timeout")]
    flaky = set()
    if again and len(again) <= args.max_retries:
        args_one = argparse.Namespace(**{**vars(args), "chunk": 1, "quiet": True})
        rerun, more = run_cases(args_one, build, again, work, "r")
        qpas += more
        flaky = {c for c in again if STATUS.get(rerun[c][0]) in ("pass", "warn")}

    tests = {}
    for c in cases:
        if c in excluded:
            tests[c] = {"result": "excluded", "expected": "excluded", "status": "excluded",
                        "reason": excluded[c]}
            continue
        st, secs, detail = raw[c]
        result, expected, status, reason = classify(c, st, fails, flakes)
        if c in flaky:
            result, status = "flake", "flake"
        t = {"result": result, "deqp": st, "expected": expected, "status": status,
             "seconds": round(secs, 3)}
        if detail and result not in ("pass",):
            t["detail"] = detail
        if reason:
            t["reason"] = reason
        tests[c] = t

    # the QPA sections of every case that did not pass
    not_passed = {c for c, t in tests.items() if t["result"] not in ("pass", "excluded")}
    qdir = os.path.join(out_dir, "qpa")
    os.makedirs(qdir, exist_ok=True)
    for q in qpas:
        for c, text in qpa_sections(q, not_passed).items():
            with open(os.path.join(qdir, c + ".qpa"), "a", encoding="utf-8") as f:
                f.write(text)
    with open(os.path.join(out_dir, "results.csv"), "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(["test", "status", "duration"])
        for c in sorted(tests):
            t = tests[c]
            w.writerow([c, t.get("deqp", "Skip") if t["result"] != "flake" else "Flake",
                        t.get("seconds", 0)])
    if not args.keep_work:
        shutil.rmtree(work, ignore_errors=True)

    counts, expected = tally(tests)
    summary = {
        "format": FORMAT, "module": args.module, "list": label, "driver": args.driver,
        "fraction": args.fraction, "profile": os.environ.get("FIXPIPE_PROFILE") or "seed",
        "texfmt": os.environ.get("FIXPIPE_TEXFMT") or "dfx24",
        "shard": [si, sn], "started": started.strftime("%Y-%m-%dT%H:%M:%SZ"),
        "seconds": round(time.time() - t0, 1), "jobs": args.jobs, "total": len(tests),
        "counts": counts, "expected": expected, "tests": tests,
    }
    status = report(summary, f"deqp-{args.module}-{args.driver}", os.path.basename(fails_file))
    summary["exit_status"] = status
    with open(os.path.join(out_dir, "summary.json"), "w", encoding="utf-8") as f:
        json.dump(summary, f, indent=1, sort_keys=True)
        f.write("\n")
    if sharded:
        fpshard.done(out_dir, "deqp", key, si, sn, status, summary="summary.json")
    print(f"fixpipe: {MODULES[args.module]} on {args.driver} took {summary['seconds']:.0f} s")
    return status


def cmd_merge(dirs, into=None):
    """The shards' summaries as one run's; with `into`, written to INTO/summary.json when no
    shard is missing."""
    first, tests, missing = join_shards(dirs, FORMAT, ("module", "list", "driver", "fraction"))
    n_shards = first["shard"][1]
    counts, expected = tally(tests)
    summary = dict(first, shard=[0, n_shards], tests=tests, counts=counts, expected=expected,
                   total=len(tests))
    status = report(summary, f"deqp-{first['module']}-{first['driver']}", f"{first['driver']}-fails.txt")
    return finish_merge(summary, status, missing, n_shards, into)


def positive(s):
    if not s.isdigit() or int(s) < 1:
        raise argparse.ArgumentTypeError(f"wants a whole number >= 1, got {s!r}")
    return int(s)


def main(argv):
    if "--sweep" in argv:
        import sweep
        return sweep.main(argv)
    if argv[:1] == ["--merge"]:
        into = None
        if argv[1:2] == ["--into"] and len(argv) > 2:
            into, argv = argv[2], argv[2:]
        if len(argv) < 2:
            print("usage: run.py --merge [--into DIR] DIR...", file=sys.stderr)
            return 2
        return cmd_merge(argv[1:], into)
    ap = argparse.ArgumentParser(prog="./fixpipe deqp", description=__doc__.splitlines()[0])
    ap.add_argument("module", choices=sorted(MODULES))
    ap.add_argument("--list", default="mustpass",
                    help="mustpass (default), all (less performance and stress), or a file "
                         "of case names and globs")
    ap.add_argument("--driver", default="fixpipe", choices=DRIVERS)
    ap.add_argument("--shard", type=parse_shard, default=None,
                    help="I/N; else from SLURM_ARRAY_TASK_* or CI_NODE_INDEX/CI_NODE_TOTAL")
    ap.add_argument("--fraction", type=positive, default=1,
                    help="run every N-th case of the list (deqp-runner's --fraction)")
    ap.add_argument("--jobs", type=positive, default=os.cpu_count() or 1)
    ap.add_argument("--timeout", type=positive,
                    default=int(os.environ.get("FIXPIPE_DEQP_TIMEOUT", 120)),
                    help="seconds a case may take (default 120)")
    ap.add_argument("--chunk", type=positive, default=500, help="cases per dEQP process")
    ap.add_argument("--max-retries", type=int, default=200,
                    help="new failures run again alone when there are at most this many")
    ap.add_argument("--out", default=None)
    ap.add_argument("--expectations", default=os.path.join(HERE, "expectations"))
    ap.add_argument("--work", default=os.environ.get("FIXPIPE_WORK", os.path.join(REPO, ".fixpipe")))
    ap.add_argument("--launcher", default=os.path.join(REPO, "fixpipe"))
    ap.add_argument("--keep-work", action="store_true", help="keep the per-process logs")
    ap.add_argument("--quiet", action="store_true", help="no progress line after each chunk")
    try:
        args = ap.parse_args(argv)
    except SystemExit as e:
        return 2 if e.code else 0
    args.out_given = args.out is not None
    args.out = args.out or os.path.join(REPO, "out", "deqp")
    return cmd_run(args)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
