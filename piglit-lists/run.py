#!/usr/bin/env python3
"""Runs a piglit list on one driver and compares the results with the driver's expectations.

usage: run.py LIST [--driver D] [--shard I/N] [--jobs J] [options]
       run.py --merge DIR...      combine the summary.json files of the shards of one run
       run.py --skips DIR...      the '<name>,Skip' lines, grouped under their reason, of the
                                  run-time skips of runs (their results directories)

The `piglit` command of ./fixpipe calls this; docs/piglit.md describes the lists, the
expectation files, sharding, the exit status and summary.json.
"""
import argparse
import bz2
import datetime
import fcntl
import glob
import gzip
import json
import os
import re
import shlex
import subprocess
import sys
import time
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "tools"))
from fpexpect import (bad_input, finish_merge, join_shards, matching, parse_shard, read_fails,  # noqa: E402
                      read_regexes, shard)
import fpshard  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
PIGLIT_DIR = os.environ.get("FIXPIPE_PIGLIT_DIR", "/usr/lib/x86_64-linux-gnu/piglit")
DRIVERS = ("fixpipe", "softpipe", "llvmpipe")
FORMAT = "fixpipe-piglit-summary/1"
# piglit results that count as another one
ALIASES = {"incomplete": "crash", "dmesg-fail": "crash", "dmesg-warn": "crash"}
COUNT_KEYS = ("pass", "warn", "fail", "crash", "timeout", "skip", "notrun", "excluded")


# ------------------------------------------------------------------ inputs
def read_list(path):
    """Test names (piglit strips everything after '#' the same way)."""
    names = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            name = line.split("#")[0].strip()
            if name:
                names.append(name)
    seen = set()
    return [n for n in names if not (n in seen or seen.add(n))]


def profile_index(names):
    """name -> (piglit profile, runs on the window system, the test's XML element as bytes)
    for the names in piglit's profiles.

    piglit gives -fbo only to its 'concurrent' tests; the others draw to a window, which the
    surfaceless platform does not have, so they run under Xvfb.
    """
    wanted, index = set(names), {}
    for profile in ("quick_gl", "quick_shader", "glslparser"):
        path = os.path.join(PIGLIT_DIR, "tests", profile + ".xml.gz")
        if not os.path.exists(path):
            continue
        with gzip.open(path, "rt") as f:
            for _, e in ET.iterparse(f):
                if e.tag != "Test":
                    continue
                name = e.get("name")
                if name in wanted and name not in index:
                    conc = [o.get("value") for o in e.findall("option")
                            if o.get("name") == "run_concurrent"]
                    index[name] = (profile, conc == ["False"], ET.tostring(e))
                e.clear()
        if len(index) == len(wanted):
            break
    return index


def write_profile(path, names, index):
    """A piglit XML profile of just these tests, copied from piglit's own profiles.

    Given a profile name and --test-list, piglit builds a test object for every one of the
    profile's tests before it starts the first (85,000 for 'quick': 5-6 s of one core per
    invocation, longer than the gles2 list's tests take). A profile of only the list's tests
    gives piglit the same test objects. Names that piglit's profiles lack are left out:
    --ignore-missing reports them notrun, as it does with the whole profile.
    """
    tests = [index[n][2] for n in names if n in index]
    with gzip.open(path, "wb", compresslevel=1) as f:
        f.write(b"<?xml version='1.0' encoding='utf-8'?>\n")
        f.write(f'<PiglitTestList count="{len(tests)}" name="fixpipe-list">'.encode())
        for t in tests:
            f.write(t)
        f.write(b"</PiglitTestList>\n")


# ------------------------------------------------------------------ running piglit
def read_results(results_dir):
    """piglit's results of one run: the final file, or the per-test files of a cut-short run."""
    for name in ("results.json.bz2", "results.json"):
        path = os.path.join(results_dir, name)
        if os.path.exists(path):
            opener = bz2.open if name.endswith(".bz2") else open
            with opener(path, "rt", encoding="utf-8") as f:
                return json.load(f).get("tests", {})
    tests = {}
    for path in glob.glob(os.path.join(results_dir, "tests", "*.json")):
        try:
            with open(path, encoding="utf-8") as f:
                tests.update(json.load(f))
        except (ValueError, OSError):
            pass  # the test being written when the run stopped
    return tests


def run_piglit(args, names, platform, index, results_dir):
    os.makedirs(results_dir, exist_ok=True)
    list_file = results_dir + ".list"
    with open(list_file, "w", encoding="utf-8") as f:
        f.write("".join(n + "\n" for n in names))
    # piglit takes an absolute path containing '.xml' as an XML profile (gzip-compressed)
    profile = os.path.abspath(results_dir + ".profile.xml.gz")
    write_profile(profile, names, index)
    piglit = args.piglit.split()
    cmd = [args.launcher, "run", "--driver", args.driver]
    if platform == "x11":
        cmd += ["--xvfb", "--"] + piglit + ["run", "-p", "glx"]
    else:
        cmd += ["--no-xvfb", "--"] + piglit + ["run", "-p", "surfaceless_egl"]
    cmd += ["--process-isolation", "true", "-j", str(args.jobs), "--timeout", str(args.timeout),
            "-l", "dummy", "-o", "--ignore-missing", "-n", f"{args.driver}-{args.label}",
            "--test-list", list_file, profile, results_dir]
    log = results_dir + ".log"
    start = time.time()
    with open(log, "w", encoding="utf-8") as f:
        f.write(" ".join(cmd) + "\n")
        f.flush()
        rc = subprocess.call(cmd, stdout=f, stderr=subprocess.STDOUT)
    results = read_results(results_dir)
    print(f"  {platform}: {len(names)} tests in {time.time() - start:.0f} s"
          + (f", piglit exit {rc}" if rc else ""), flush=True)
    if not results:
        with open(log, encoding="utf-8", errors="replace") as f:
            tail = f.read().splitlines()[-15:]
        print("\n".join("  | " + ln for ln in tail))
        print(f"  piglit wrote no results (log: {os.path.relpath(log, REPO)})")
    return {k.lower(): v for k, v in results.items()}


NO_DISPLAY = "XOpenDisplay failed"


def _output(res):
    return ((res or {}).get("out") or "") + ((res or {}).get("err") or "")


# ------------------------------------------------------------------ comparing
def classify(name, res, fails, flakes):
    """(result, expected, status, reason) of one test.  status: ok (a pass), expected (a
    listed failure), skipped (a run-time skip listed as Skip, for the feature it names),
    flake, unexpected (anything else not listed: a new failure, crash or skip) or
    unexpected_pass (a listed test that passes: its line must go)."""
    actual = res["result"] if res else "notrun"
    actual = ALIASES.get(actual, actual)
    if actual == "notrun" and res and res.get("returncode") not in (None, 0):
        # piglit says notrun when a test enumerates subtests and then reports only a
        # whole-test result; it ran and exited with an error: a failure.
        actual = "fail"
    if actual not in COUNT_KEYS:
        actual = "notrun"
    flake = matching(flakes, name)
    if flake is not None:
        return actual, "flake", "flake", flake
    expected, reason = fails.get(name.lower(), ("pass", ""))
    if actual in ("pass", "warn"):
        return actual, expected, "ok" if expected == "pass" else "unexpected_pass", reason
    if actual == expected:
        return actual, expected, "skipped" if actual == "skip" else "expected", reason
    return actual, expected, "unexpected", reason


def report(summary, label, fails_file, raw=None):
    """Prints the differences and the counts; returns the exit status."""
    raw = raw or {}
    for name, t in sorted(summary["tests"].items()):
        st = t["status"]
        if st == "unexpected_pass":
            print(f"  UnexpectedPass {name} (expected {t['expected']}: remove its line from "
                  f"{fails_file})")
        elif st == "unexpected":
            print(f"  {t['result'].upper():<12} {name} (expected {t['expected']})")
            res = raw.get(name.lower()) or {}
            if res.get("command"):
                print(f"               {res['command']}")
            out = (res.get("out") or "") + (res.get("err") or "")
            for line in out.strip().splitlines()[-6:]:
                print(f"               | {line}")
    c = summary["counts"]
    print(f"{label}: " + ", ".join(f"{c[k]} {k}" for k in COUNT_KEYS
                                   if c[k] or k in ("pass", "fail", "crash", "skip")))
    e = summary["expected"]
    print(f"{label}: apart from the passes: {e['expected_fail']} listed failures, "
          f"{e['skipped']} listed skips, {e['flake']} flakes, {e['excluded']} not run")
    print(f"{label}: {e['passed']} passed, {e['unexpected']} failed")
    return 1 if e["unexpected"] else 0


def tally(tests):
    """The counts of the results, and of the statuses: passed counts passes alone; a
    listed failure or skip, a flake and an excluded test are counted apart; failed is
    every test not as listed, an unexpected pass among them."""
    counts = dict.fromkeys(COUNT_KEYS, 0)
    expected = {"passed": 0, "unexpected": 0, "unexpected_pass": 0, "expected_fail": 0,
                "skipped": 0, "flake": 0, "excluded": 0}
    key = {"ok": "passed", "expected": "expected_fail", "skipped": "skipped",
           "flake": "flake", "excluded": "excluded"}
    for t in tests.values():
        counts[t["result"]] += 1
        if t["status"] in ("unexpected", "unexpected_pass"):
            expected["unexpected"] += 1
            expected["unexpected_pass"] += t["status"] == "unexpected_pass"
        else:
            expected[key[t["status"]]] += 1
    return counts, expected


# ------------------------------------------------------------------ commands
def cmd_run(args):
    if os.sep in args.list:
        list_file = args.list
        args.label = re.sub(r"\.txt$", "", os.path.basename(args.list))
    else:
        args.label = re.sub(r"\.txt$", "", args.list)
        list_file = os.path.join(HERE, args.label + ".txt")
    if not os.path.exists(list_file):
        avail = sorted(f[:-4] for f in os.listdir(HERE) if f.endswith(".txt"))
        print(f"fixpipe: no list {list_file} (lists: {', '.join(avail)})", file=sys.stderr)
        return 2
    names = read_list(list_file)
    exp = args.expectations
    fails_file = os.path.join(exp, f"{args.driver}-fails.txt")
    fails = read_fails(fails_file)
    skips = read_regexes(os.path.join(exp, f"{args.driver}-skips.txt"))
    flakes = read_regexes(os.path.join(exp, f"{args.driver}-flakes.txt"))

    tests = {}
    excluded = {}
    for n in names:
        reason = matching(skips, n)
        if reason is not None:
            excluded[n] = reason
    to_run = [n for n in names if n not in excluded]
    si, sn, sharded = fpshard.resolve(args.shard)
    out_name = f"{args.driver}-{args.label}" + (f"-s{si}of{sn}" if sharded else "")
    if sn > 1:
        # The split is over the whole list, so the excluded tests are shared out too.
        mine = set(shard(names, si, sn))
        to_run = [n for n in to_run if n in mine]
        excluded = {n: r for n, r in excluded.items() if n in mine}
    out_dir = os.path.join(args.out, out_name)
    os.makedirs(out_dir, exist_ok=True)
    # Two runs of one list on one driver (two `./fixpipe check` at once) would write into the
    # same piglit directories and mix their results: the second waits for the first.
    lock = open(out_dir + ".lock", "w")
    try:
        fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        print(f"fixpipe: waiting for another run of {out_name} to finish", flush=True)
        fcntl.flock(lock, fcntl.LOCK_EX)
    for stale in ("summary.json",):
        if os.path.exists(os.path.join(out_dir, stale)):
            os.remove(os.path.join(out_dir, stale))
    key = {"list": args.label, "driver": args.driver,
           "profile": os.environ.get("FIXPIPE_PROFILE") or "seed"}
    if sharded:
        # a result directory named on the command line is one campaign's (docs/cluster.md)
        fpshard.claim(args.out if args.out_given else out_dir, out_dir, "piglit", key, si, sn)

    started = datetime.datetime.now(datetime.timezone.utc)
    t0 = time.time()
    print(f"fixpipe: piglit {args.label} on {args.driver}"
          + (f", shard {si}/{sn}" if sn > 1 else "")
          + f": {len(to_run)} tests, {len(excluded)} excluded, "
          f"results in {os.path.relpath(out_dir, REPO)}", flush=True)

    index = profile_index(to_run)
    parts = {}
    for n in to_run:
        window = n in index and index[n][1]
        parts.setdefault("x11" if window else "surfaceless", []).append(n)
    profiles_used = {index[n][0] for n in to_run if n in index}
    raw, platform_of = {}, {}
    for platform in ("surfaceless", "x11"):
        part = parts.get(platform)
        if not part:
            continue
        # one piglit run a platform, on a profile of the part's tests alone
        results = run_piglit(args, part, platform, index, os.path.join(out_dir, platform))
        # Xvfb now and then refuses a connection under load: such a test never ran, so it
        # gets one more go rather than a failure.
        again = [n for n in part if NO_DISPLAY in _output(results.get(n.lower()))]
        if again:
            results.update(run_piglit(args, again, platform, index,
                                      os.path.join(out_dir, platform + "-again")))
        for n in part:
            platform_of[n] = platform
            if n.lower() in results:
                raw[n.lower()] = results[n.lower()]

    for n in names:
        if sn > 1 and n not in excluded and n not in platform_of:
            continue  # another shard's
        if n in excluded:
            tests[n] = {"result": "excluded", "expected": "excluded", "status": "excluded",
                        "reason": excluded[n]}
            continue
        res = raw.get(n.lower())
        result, expected, status, reason = classify(n, res, fails, flakes)
        t = {"result": result, "expected": expected, "status": status,
             "platform": platform_of[n]}
        if res and isinstance(res.get("time"), dict):
            t["seconds"] = round(res["time"].get("end", 0) - res["time"].get("start", 0), 3)
        if reason:
            t["reason"] = reason
        tests[n] = t

    counts, expected = tally(tests)
    summary = {
        "format": FORMAT, "list": args.label, "driver": args.driver,
        "profile": os.environ.get("FIXPIPE_PROFILE") or "seed",
        "shard": [si, sn], "started": started.strftime("%Y-%m-%dT%H:%M:%SZ"),
        "seconds": round(time.time() - t0, 1), "jobs": args.jobs,
        "piglit_profiles": sorted(profiles_used),
        "total": len(tests), "counts": counts, "expected": expected, "tests": tests,
    }
    label = f"piglit-{args.label}-{args.driver}" + (f"-s{si}of{sn}" if sn > 1 else "")
    status = report(summary, label, os.path.basename(fails_file), raw)
    summary["exit_status"] = status
    with open(os.path.join(out_dir, "summary.json"), "w", encoding="utf-8") as f:
        json.dump(summary, f, indent=1, sort_keys=True)
        f.write("\n")
    if sharded:
        fpshard.done(out_dir, "piglit", key, si, sn, status, summary="summary.json")
    print(f"fixpipe: piglit {args.label} on {args.driver} took {summary['seconds']:.0f} s")
    return status


def cmd_merge(dirs, into=None):
    """The shards' summaries as one run's; with `into`, written to INTO/summary.json (only
    when no shard is missing: a partial merge never replaces a whole run's summary)."""
    first, tests, missing = join_shards(dirs, FORMAT, ("list", "driver"))
    n_shards = first["shard"][1]
    counts, expected = tally(tests)
    summary = dict(first, shard=[0, n_shards], tests=tests, counts=counts, expected=expected,
                   total=len(tests))
    summary["seconds"] = round(sum(json.load(open(d if d.endswith(".json") else
                                                  os.path.join(d, "summary.json")))["seconds"]
                                   for d in dirs), 1)
    status = report(summary, f"piglit-{first['list']}-{first['driver']}",
                    f"{first['driver']}-fails.txt")
    return finish_merge(summary, status, missing, n_shards, into)


def skip_reason(res):
    """The missing feature a skipped test names (piglit's 'Test requires ...' line)."""
    lines = [ln.strip() for ln in _output(res).splitlines() if ln.strip()]
    said = [ln for ln in lines if re.search(r"requir|support|not available", ln, re.I)]
    if said:
        return said[-1]
    # a parser test piglit skips before it runs: its requirements are its command's last
    # words (GLSL version, 'es', extensions; '!EXT' for one the driver must not have)
    words = shlex.split((res or {}).get("command") or "")
    samples = [w.split("=", 1)[1] for w in words if w.startswith("-samples=")]
    if samples:
        return (f"a default framebuffer of {samples[0]} samples, which the driver's visuals "
                "do not offer (skipped before it ran)")
    if len(words) > 3 and "glslparsertest" in os.path.basename(words[0]):
        return ("piglit runs this parser test only for GLSL " + " ".join(words[3:])
                + " (skipped before it ran)")
    return ("piglit skipped it before it ran: the GL version or extensions it needs are not "
            "exposed (wflinfo)")


def cmd_skips(dirs):
    """Prints Skip lines for fails.txt: every run-time skip of the runs, under its reason."""
    by_reason = {}
    for d in dirs:
        with open(os.path.join(d, "summary.json"), encoding="utf-8") as f:
            tests = json.load(f)["tests"]
        raw = {}
        for platform in ("surfaceless", "x11", "surfaceless-again", "x11-again"):
            raw.update(read_results(os.path.join(d, platform)))
        for name, t in tests.items():
            if t["result"] == "skip":
                by_reason.setdefault(skip_reason(raw.get(name.lower())), set()).add(name)
    for reason in sorted(by_reason):
        print(f"# skips: {reason}")
        for name in sorted(by_reason[reason]):
            print(f"{name},Skip")
        print()
    return 0


def main(argv):
    if argv[:1] == ["--skips"]:
        return cmd_skips(argv[1:])
    if argv[:1] == ["--merge"]:
        into = None
        if argv[1:2] == ["--into"] and len(argv) > 2:
            into, argv = argv[2], argv[2:]
        if len(argv) < 2:
            print("usage: run.py --merge [--into DIR] DIR...", file=sys.stderr)
            return 2
        return cmd_merge(argv[1:], into)
    ap = argparse.ArgumentParser(prog="./fixpipe piglit", description=__doc__.splitlines()[0])
    ap.add_argument("list")
    ap.add_argument("--driver", default="fixpipe")
    ap.add_argument("--shard", type=parse_shard, default=None,
                    help="I/N; else from SLURM_ARRAY_TASK_* or CI_NODE_INDEX/CI_NODE_TOTAL")
    ap.add_argument("--jobs", type=int, default=int(os.environ.get("FIXPIPE_PIGLIT_JOBS", 2)))
    ap.add_argument("--timeout", type=int,
                    default=int(os.environ.get("FIXPIPE_PIGLIT_TIMEOUT", 300)))
    ap.add_argument("--out", default=None)
    ap.add_argument("--expectations", default=os.environ.get(
        "FIXPIPE_PIGLIT_EXPECTATIONS", os.path.join(HERE, "expectations")))
    ap.add_argument("--launcher", default=os.path.join(REPO, "fixpipe"))
    ap.add_argument("--piglit", default=os.environ.get("FIXPIPE_PIGLIT", "piglit"),
                    help="piglit command (the runner's tests give a fake one)")
    try:
        args = ap.parse_args(argv)
    except SystemExit as e:
        return 2 if e.code else 0
    args.out_given = args.out is not None
    args.out = args.out or os.environ.get("FIXPIPE_PIGLIT_OUT", os.path.join(REPO, "out", "piglit"))
    if args.driver not in DRIVERS:
        print(f"fixpipe: unknown driver '{args.driver}' (accepted: {', '.join(DRIVERS)})",
              file=sys.stderr)
        return 2
    return cmd_run(args)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
