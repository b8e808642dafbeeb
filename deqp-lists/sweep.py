#!/usr/bin/env python3
"""Conformance against precision: a dEQP list under each precision setting of the sweep.

usage: ./fixpipe deqp gles2|gles3 --sweep [--grid full|quick] [--list FILE] [--fraction N]
                                          [--out DIR] [--jobs J]

For every setting of tools/fp-sweep's grid (FIXPIPE_PROFILE=seed:KEY=M.N and FIXPIPE_TEXFMT:
one register's fraction bits, or the texture path's mantissa, at a time), plus binary32
texture arithmetic, runs the list (default deqp-lists/sweep-MODULE.txt: the texture,
rasterization, clipping, depth and multisample groups) on fixpipe and counts, per group, the
cases that pass.  Writes OUT/sweep.json, OUT/sweep.md (the table, and per family the
narrowest setting that fails no case the default setting passes) and OUT/sweep.png (the
chart); docs/deqp.md shows them.  Default OUT: out/deqp/sweep-MODULE.
"""
import argparse
import importlib.machinery
import importlib.util
import json
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
PASSING = ("pass", "warn", "flake")


def sweep_grid(name):
    """fp-sweep's grid (one setting a register family), and binary32 texture arithmetic."""
    path = os.path.join(REPO, "tools", "fp-sweep")
    loader = importlib.machinery.SourceFileLoader("fp_sweep", path)
    spec = importlib.util.spec_from_loader("fp_sweep", loader)
    mod = importlib.util.module_from_spec(spec)
    loader.exec_module(mod)
    grid = mod.full_grid() if name == "full" else mod.quick_grid()
    if name == "full":
        grid.append(("float", "dfx mantissa", 24, "seed", "float"))
    return [g for g in grid]


def group_of(case):
    """dEQP-GLES2.functional.texture.filtering.2d.x -> functional.texture.filtering"""
    parts = case.split(".")
    return ".".join(parts[1:4])


def run_setting(args, label, profile, texfmt):
    out = os.path.join(args.out, "runs")
    # a setting's directory holds this run alone (an earlier sweep's, of another
    # list or fraction, would be read as this one's)
    shutil.rmtree(os.path.join(out, label.replace(" ", "_")), ignore_errors=True)
    env = dict(os.environ, FIXPIPE_PROFILE=profile, FIXPIPE_TEXFMT=texfmt)
    env.pop("FIXPIPE_DEBUG", None)
    empty = os.path.join(args.out, "no-expectations")
    os.makedirs(empty, exist_ok=True)
    cmd = [sys.executable, os.path.join(HERE, "run.py"), args.module, "--list", args.list,
           "--driver", "fixpipe", "--out", os.path.join(out, label.replace(" ", "_")),
           "--expectations", empty, "--quiet", "--max-retries", "0", "--jobs", str(args.jobs),
           "--launcher", args.launcher]
    if args.fraction > 1:
        cmd += ["--fraction", str(args.fraction)]
    p = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    sums = [os.path.join(dp, "summary.json") for dp, _, fs in
            os.walk(os.path.join(out, label.replace(" ", "_"))) if "summary.json" in fs]
    if not sums:
        print(p.stdout[-3000:], file=sys.stderr)
        raise SystemExit(f"fixpipe: the {label} run wrote no summary")
    with open(sums[0], encoding="utf-8") as f:
        return json.load(f)["tests"]


def narrowest(settings, fails_beyond_default):
    """Per family, the setting with the fewest bits that fails nothing the default passes."""
    best = {}
    for label, family, bits, _, _ in settings:
        if family in ("default",) or bits is None:
            continue
        if fails_beyond_default[label] == 0 and (family not in best or bits < best[family][1]):
            best[family] = (label, bits)
    return best


def write_outputs(args, settings, results):
    groups = sorted({group_of(c) for r in results.values() for c in r})
    table = {label: {} for label in results}
    for label, tests in results.items():
        for c, t in tests.items():
            g = table[label].setdefault(group_of(c), [0, 0])
            g[0] += t["result"] in PASSING
            g[1] += t["result"] not in ("notsupported", "excluded")
    default = next(s[0] for s in settings if s[1] == "default")
    base = {c for c, t in results[default].items() if t["result"] in PASSING}
    beyond = {label: sum(1 for c in base if tests.get(c, {}).get("result") not in PASSING)
              for label, tests in results.items()}
    best = narrowest(settings, beyond)
    data = {"module": args.module, "list": args.list, "fraction": args.fraction,
            "settings": [{"label": s[0], "family": s[1], "bits": s[2], "profile": s[3],
                          "texfmt": s[4], "fails_beyond_default": beyond[s[0]]}
                         for s in settings],
            "groups": {g: {label: table[label].get(g, [0, 0]) for label in results}
                       for g in groups},
            "narrowest": {f: v[0] for f, v in best.items()}}
    with open(os.path.join(args.out, "sweep.json"), "w", encoding="utf-8") as f:
        json.dump(data, f, indent=1)
        f.write("\n")

    labels = [s[0] for s in settings]
    md = [f"Cases of each group that pass on fixpipe under each setting ({args.module}, "
          f"`{os.path.relpath(args.list, REPO) if os.sep in args.list else args.list}`"
          + (f", one case in {args.fraction}" if args.fraction > 1 else "") + "); "
          "*beyond default*: cases the default setting passes and this one fails.", "",
          "| setting | FIXPIPE_PROFILE | FIXPIPE_TEXFMT | pass | beyond default |",
          "|---|---|---|---:|---:|"]
    for s in settings:
        tot = [0, 0]
        for g in groups:
            v = table[s[0]].get(g, [0, 0])
            tot[0] += v[0]
            tot[1] += v[1]
        md.append(f"| {s[0]} | `{s[3]}` | `{s[4]}` | {tot[0]} / {tot[1]} | {beyond[s[0]]} |")
    md += ["", "| group | " + " | ".join(labels) + " |",
           "|---|" + "---:|" * len(labels)]
    for g in groups:
        md.append(f"| {g} | " + " | ".join(
            "{}/{}".format(*table[label].get(g, [0, 0])) for label in labels) + " |")
    md += ["", "Narrowest setting per family that fails nothing the default passes: "
           + (", ".join(f"{f}: {v[0]}" for f, v in sorted(best.items())) or "none") + "."]
    with open(os.path.join(args.out, "sweep.md"), "w", encoding="utf-8") as f:
        f.write("\n".join(md) + "\n")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    frac = [[(table[label].get(g, [0, 0])[0] / table[label][g][1])
             if table[label].get(g, [0, 0])[1] else float("nan") for label in labels]
            for g in groups]
    fig, ax = plt.subplots(figsize=(1.2 + 0.42 * len(labels), 1.4 + 0.32 * len(groups)))
    im = ax.imshow(frac, vmin=0.8, vmax=1.0, cmap="RdYlGn", aspect="auto")
    ax.set_xticks(range(len(labels)))
    ax.set_xticklabels(labels, rotation=60, ha="right", fontsize=8)
    ax.set_yticks(range(len(groups)))
    ax.set_yticklabels(groups, fontsize=8)
    for i, g in enumerate(groups):
        for j, label in enumerate(labels):
            v = table[label].get(g, [0, 0])
            if v[1] and v[0] < v[1]:
                ax.text(j, i, str(v[1] - v[0]), ha="center", va="center", fontsize=6)
    ax.set_title(f"dEQP {args.module} on fixpipe: share of each group passing per precision "
                 "setting (numbers: cases failing)", fontsize=9)
    fig.colorbar(im, ax=ax, fraction=0.03, pad=0.02)
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "sweep.png"), dpi=90)
    print("\n".join(md[:len(settings) + 4]))
    print(md[-1])
    print(f"fixpipe: sweep written to {os.path.relpath(args.out, REPO)}/ "
          "(sweep.json, sweep.md, sweep.png)")


def main(argv):
    ap = argparse.ArgumentParser(prog="./fixpipe deqp MODULE --sweep",
                                 description=__doc__.splitlines()[0])
    ap.add_argument("module", choices=("gles2", "gles3"))
    ap.add_argument("--sweep", action="store_true")
    ap.add_argument("--grid", choices=("full", "quick"), default="full")
    ap.add_argument("--list", default=None)
    ap.add_argument("--fraction", type=int, default=1)
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--out", default=None)
    ap.add_argument("--launcher", default=os.path.join(REPO, "fixpipe"))
    try:
        args = ap.parse_args(argv)
    except SystemExit as e:
        return 2 if e.code else 0
    args.list = args.list or os.path.join(HERE, f"sweep-{args.module}.txt")
    args.out = args.out or os.path.join(REPO, "out", "deqp", f"sweep-{args.module}")
    os.makedirs(args.out, exist_ok=True)
    settings = sweep_grid(args.grid)
    results = {}
    for k, (label, _, _, profile, texfmt) in enumerate(settings):
        print(f"fixpipe: sweep {k + 1}/{len(settings)}: {label} "
              f"(FIXPIPE_PROFILE={profile} FIXPIPE_TEXFMT={texfmt})", flush=True)
        results[label] = run_setting(args, label, profile, texfmt)
    write_outputs(args, settings, results)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
