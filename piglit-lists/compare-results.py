#!/usr/bin/env python3
"""Compares a piglit results directory with the expectations of one driver.

usage: compare-results.py RESULTS_DIR LIST_FILE FAILS_FILE SKIPS_FILE LABEL

Expectations follow Mesa CI: FAILS_FILE has `<test name>,Fail|Crash|Timeout` lines (a `# reason`
comment line above each), SKIPS_FILE has one regex a line for tests that are not run at all.
A test that runs and reports skip is a difference too: a driver that stops exposing a feature
must not turn the list green. An expected failure that now passes is reported, not fatal, so the
expectation can be removed.

Prints every result that differs from the expectations, the counts, and last
`LABEL: N passed, N failed` where passed counts tests that met their expectation.
Exit status 1 on a new failure, crash, timeout, skip or missing result.
"""
import bz2
import json
import os
import re
import sys

STATUSES = {"Fail": "fail", "Crash": "crash", "Timeout": "timeout"}


def read_lines(path):
    if not os.path.exists(path):
        return []
    with open(path, encoding="utf-8") as f:
        return [ln.split("#")[0].strip() if not ln.lstrip().startswith("#") else ""
                for ln in f.read().splitlines()]


def read_list(path):
    # piglit's --test-list strips everything after '#' the same way
    with open(path, encoding="utf-8") as f:
        return [t.split("#")[0].strip() for t in f if t.split("#")[0].strip()]


def read_fails(path):
    fails = {}
    for n, line in enumerate(read_lines(path), 1):
        if not line:
            continue
        name, sep, status = line.rpartition(",")
        if not sep or status not in STATUSES:
            sys.exit(f"{path}:{n}: expected '<test name>,Fail|Crash|Timeout', got {line!r}")
        fails[name.lower()] = STATUSES[status]
    return fails


def read_results(results_dir):
    for name in ("results.json.bz2", "results.json"):
        path = os.path.join(results_dir, name)
        if os.path.exists(path):
            opener = bz2.open if name.endswith(".bz2") else open
            with opener(path, "rt", encoding="utf-8") as f:
                data = json.load(f)
            return {k.lower(): v for k, v in data.get("tests", {}).items()}
    return {}


def main():
    results_dir, list_file, fails_file, skips_file, label = sys.argv[1:6]
    tests = read_list(list_file)
    fails = read_fails(fails_file)
    skips = [re.compile(r) for r in read_lines(skips_file) if r]
    results = read_results(results_dir)

    counts = {"pass": 0, "warn": 0, "fail": 0, "crash": 0, "timeout": 0, "skip": 0,
              "notrun": 0}
    passed = failed = 0
    for test in tests:
        key = test.lower()
        if any(r.search(test) for r in skips):
            counts["skip"] += 1
            passed += 1
            continue
        res = results.get(key)
        actual = res["result"] if res else "notrun"
        if actual in ("incomplete", "dmesg-fail", "dmesg-warn"):
            actual = "crash"
        counts[actual if actual in counts else "notrun"] += 1
        expected = fails.get(key, "pass")
        if actual in ("pass", "warn") and expected == "pass":
            passed += 1
            if actual == "warn":
                print(f"  warn         {test}")
        elif actual == expected:
            passed += 1
        elif actual in ("pass", "warn"):
            passed += 1
            print(f"  UnexpectedPass {test} (expected {expected}: remove it from "
                  f"{os.path.basename(fails_file)})")
        else:
            failed += 1
            out = (res or {}).get("out", "") + (res or {}).get("err", "")
            print(f"  {actual.upper():<12} {test} (expected {expected})")
            if res and res.get("command"):
                print(f"               {res['command']}")
            for line in out.strip().splitlines()[-6:]:
                print(f"               | {line}")

    known = set(t.lower() for t in tests)
    stale = sorted(t for t in fails if t not in known)
    for t in stale:
        print(f"  note: {os.path.basename(fails_file)} names {t!r}, which is not in the list")

    print(f"{label}: " + ", ".join(f"{v} {k}" for k, v in counts.items() if v or k in
                                   ("pass", "fail", "crash", "skip")))
    print(f"{label}: {passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
