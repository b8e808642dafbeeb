"""Expectation files in Mesa CI's format, shared by the piglit and dEQP runners.

DRIVER-fails.txt   '<test name>,Fail|Crash|Timeout|Skip' a line (Skip: a test that skips at run
                   time, for the feature the driver does not have that its reason names)
DRIVER-flakes.txt  a regular expression a line: any result of a matching test is accepted
DRIVER-skips.txt   a regular expression a line: matching tests are not run

Every entry has its reason in the '#' comment line(s) above it: a comment is the reason of
the entries that follow it up to a blank line or the next comment.  A malformed line is an
input error (exit status 2), never a silent pass.
"""
import argparse
import json
import os
import re
import sys

EXPECT = {"Fail": "fail", "Crash": "crash", "Timeout": "timeout", "Skip": "skip"}


def bad_input(msg):
    """A broken list or expectation file: exit status 2, not the 1 of a test failure."""
    print(f"fixpipe: {msg}", file=sys.stderr)
    sys.exit(2)


def read_entries(path):
    """(entry, reason, line number) for each non-comment line; reason is the '#' lines above
    it (a run of entries shares the comment before the run)."""
    entries, comment, after_entry = [], [], False
    try:
        f = open(path, encoding="utf-8")
    except FileNotFoundError:
        return entries
    with f:
        for n, line in enumerate(f, 1):
            s = line.strip()
            if not s:
                comment, after_entry = [], False
            elif s.startswith("#"):
                if after_entry:
                    comment, after_entry = [], False
                comment.append(s.lstrip("#").strip())
            else:
                entries.append((s, " ".join(comment), n))
                after_entry = True
    return entries


def read_fails(path, fold_case=True):
    """name -> (expected result, reason).  piglit's names are case-insensitive, dEQP's not."""
    fails = {}
    for line, reason, n in read_entries(path):
        name, sep, status = line.rpartition(",")
        if not sep or status not in EXPECT:
            bad_input(f"{path}:{n}: expected '<test name>,Fail|Crash|Timeout|Skip', got {line!r}")
        if not reason:
            bad_input(f"{path}:{n}: {name} has no '# reason' line above it")
        fails[name.lower() if fold_case else name] = (EXPECT[status], reason)
    return fails


def read_regexes(path):
    out = []
    for line, reason, n in read_entries(path):
        try:
            out.append((re.compile(line), reason))
        except re.error as e:
            bad_input(f"{path}:{n}: bad regex {line!r}: {e}")
    return out


def matching(regexes, name):
    """The reason of the first regex that matches name, or None."""
    for r, reason in regexes:
        if r.search(name):
            return reason or r.pattern
    return None


def shard(names, i, n):
    """Round-robin over the sorted names: every test in exactly one shard, sizes within one."""
    return [t for k, t in enumerate(sorted(names)) if k % n == i - 1]


def parse_shard(s):
    """--shard I/N for argparse."""
    m = re.fullmatch(r"(\d+)/(\d+)", s)
    if not m or not 1 <= int(m.group(1)) <= int(m.group(2)):
        raise argparse.ArgumentTypeError(f"--shard wants I/N with 1 <= I <= N, got {s!r}")
    return int(m.group(1)), int(m.group(2))


def finish_merge(summary, status, missing, n_shards, into):
    """The end of a merge of shards: with a shard missing, status 1 and nothing written
    (a merge never reports a pass without every shard); otherwise the merged summary, with
    its exit status, into DIR/summary.json when `into` is given.  Returns the status."""
    if missing:
        print(f"fixpipe: shards {missing} of {n_shards} are missing: the run is incomplete")
        return 1
    if into:
        summary["exit_status"] = status
        os.makedirs(into, exist_ok=True)
        with open(os.path.join(into, "summary.json"), "w", encoding="utf-8") as f:
            json.dump(summary, f, indent=1, sort_keys=True)
            f.write("\n")
    return status


def join_shards(dirs, fmt, key):
    """The summaries of one run's shards (DIR/summary.json or the files): (the first summary,
    every test's entry, the shard numbers missing).  A file of another format or another run
    (the fields in `key` differ) and a test in two shards are input errors."""
    tests, first, seen = {}, None, []
    for d in dirs:
        path = d if d.endswith(".json") else d.rstrip("/") + "/summary.json"
        try:
            with open(path, encoding="utf-8") as f:
                s = json.load(f)
        except (OSError, ValueError) as e:
            bad_input(f"{path}: {e}")
        if s.get("format") != fmt:
            bad_input(f"{path}: not a {fmt} file")
        first = first or s
        if [s[k] for k in key] != [first[k] for k in key]:
            bad_input(f"{path}: another run ({', '.join(str(s[k]) for k in key)})")
        seen.append(s["shard"][0])
        for n, t in s["tests"].items():
            if n in tests:
                bad_input(f"{path}: {n!r} is in two shards")
            tests[n] = t
    n_shards = first["shard"][1]
    return first, tests, sorted(set(range(1, n_shards + 1)) - set(seen))
