#!/usr/bin/env python3
"""fp-report: writes docs/conformance.md from the results already on disk: the piglit
summaries of the piglit runner (out/piglit/DRIVER-LIST[-sIofN]/summary.json, format in
docs/piglit.md), of the dEQP runner (out/deqp/DRIVER-MODULE-LIST/summary.json, docs/deqp.md)
and the trace results of tools/fp-trace (out/traces/NAME/result.json).
Heat maps of the worst frames go to docs/img/conformance/.

`./fixpipe report` runs the traces first and then this; `--piglit` runs the lists too.

usage: fp-report.py [--out docs/conformance.md] [--lists] [--deqp]   (--help says more)
"""
import argparse
import glob
import json
import math
import os
import platform
import re
import shutil
import subprocess
import sys
import time

REPO = os.path.dirname(os.path.dirname(os.path.realpath(__file__)))
DRIVERS = ("fixpipe", "softpipe", "llvmpipe")
TESTED = ("fixpipe", "softpipe")
IMG_REL = "img/conformance"
WORST_ROWS = 5
FAILING = ("fail", "crash", "timeout")


def list_names():
    return sorted(os.path.basename(p)[:-4] for p in glob.glob(os.path.join(REPO, "piglit-lists",
                                                                            "*.txt")))


# ------------------------------------------------------------------ piglit
def read_summary(driver, lst):
    """One run's summary, shards merged (the union of their tests, counts summed)."""
    base = os.path.join(REPO, "out", "piglit", f"{driver}-{lst}")
    paths = [os.path.join(base, "summary.json")]
    if not os.path.exists(paths[0]):
        paths = sorted(glob.glob(base + "-s*of*/summary.json"))
    runs = []
    for p in paths:
        try:
            with open(p, encoding="utf-8") as f:
                d = json.load(f)
        except (OSError, ValueError):
            continue
        if str(d.get("format", "")).startswith("fixpipe-piglit-summary/"):
            runs.append(d)
    if not runs:
        return None
    merged = {"counts": {}, "tests": {}, "seconds": 0.0, "started": None, "shards": len(runs),
              "total": 0}
    for d in runs:
        for k, v in d.get("counts", {}).items():
            merged["counts"][k] = merged["counts"].get(k, 0) + v
        merged["tests"].update(d.get("tests", {}))
        merged["seconds"] += d.get("seconds", 0) or 0
        merged["total"] += d.get("total", 0) or 0
        s = d.get("started")
        if s and (merged["started"] is None or s < merged["started"]):
            merged["started"] = s
    if len(runs) > 1:
        n = runs[0].get("shard", [1, len(runs)])[1]
        merged["incomplete"] = len(runs) != n
    return merged


def piglit_section():
    out = ["## piglit", ""]
    lists = [lst for lst in list_names()
             if any(read_summary(d, lst) for d in DRIVERS)]
    if not lists:
        out += ["No piglit summaries in `out/piglit/` yet: run `./fixpipe report --piglit` "
                "(or `./fixpipe piglit LIST --driver D` for each list and driver).", ""]
        return out
    out += ["Counts over the tests of each list (`./fixpipe piglit LIST --driver D`, "
            "docs/piglit.md): *excluded* are tests a driver's `skips.txt` keeps out of the "
            "run; *skip* are tests that ran and reported skip, each listed in the driver's "
            "`fails.txt` as `Skip` under the extension or version it lacks (an unlisted skip "
            "fails the list). All runs on the same machine; the date is when each run "
            "started.", "",
            "| list | driver | tests | pass | fail | crash | timeout | skip | excluded | run |",
            "|---|---|---:|---:|---:|---:|---:|---:|---:|---|"]
    gaps = []
    for lst in lists:
        sums = {d: read_summary(d, lst) for d in DRIVERS}
        for d in DRIVERS:
            s = sums[d]
            if not s:
                out.append(f"| {lst} | {d} | – | – | – | – | – | – | – | not run |")
                continue
            c = s["counts"]
            when = (s["started"] or "?").replace("T", " ").rstrip("Z")
            extra = f", {s['shards']} shards" if s["shards"] > 1 else ""
            if s.get("incomplete"):
                extra += " (shards missing)"
            out.append(f"| {lst} | {d} | {s['total']} | {c.get('pass', 0) + c.get('warn', 0)} |"
                       f" {c.get('fail', 0)} | {c.get('crash', 0)} | {c.get('timeout', 0)} |"
                       f" {c.get('skip', 0)} | {c.get('excluded', 0)} |"
                       f" {when}, {s['seconds']:.0f} s{extra} |")
        fx, ll = sums["fixpipe"], sums["llvmpipe"]
        if fx and ll:
            lt = ll["tests"]
            bad = sorted(t for t, r in fx["tests"].items()
                         if r.get("result") in FAILING
                         and lt.get(t, {}).get("result") in ("pass", "warn"))
            listed = [t for t in bad if fx["tests"][t].get("expected") in FAILING
                      and fx["tests"][t].get("reason")]
            gaps.append((lst, bad, listed, fx))
    out.append("")
    if gaps:
        out += ["### fixpipe failures that llvmpipe passes", "",
                "Each should be in `piglit-lists/expectations/fixpipe-fails.txt` with a "
                "`# reason` line (a limit of the modeled hardware, or a known bug).", "",
                "| list | fixpipe fails, llvmpipe passes | in the expectations with a reason |",
                "|---|---:|---:|"]
        for lst, bad, listed, _ in gaps:
            out.append(f"| {lst} | {len(bad)} | {len(listed)} |")
        out.append("")
        for lst, bad, listed, fx in gaps:
            missing = [t for t in bad if t not in listed]
            if missing:
                out.append(f"Not (yet) explained in `{lst}` ({len(missing)}):")
                out.append("")
                for t in missing[:25]:
                    r = fx["tests"][t]
                    out.append(f"- `{t}`: {r.get('result')}"
                               f" (expected {r.get('expected', '?')})")
                if len(missing) > 25:
                    out.append(f"- … and {len(missing) - 25} more (summary.json)")
                out.append("")
        reasons = {}
        for lst, bad, listed, fx in gaps:
            for t in listed:
                reasons.setdefault(fx["tests"][t]["reason"], []).append(t)
        if reasons:
            out += ["Reasons given, by how many such tests they cover:", "",
                    "| tests | reason |", "|---:|---|"]
            for r, ts in sorted(reasons.items(), key=lambda kv: -len(kv[1]))[:20]:
                out.append(f"| {len(ts)} | {r.lstrip('# ').replace('|', '/')} |")
            out.append("")
    return out


# ------------------------------------------------------------------ dEQP
def read_deqp(driver, module, lst):
    """A dEQP run's summary (deqp-lists/run.py), shards merged; None if not run."""
    base = os.path.join(REPO, "out", "deqp", f"{driver}-{module}-{lst}")
    paths = [os.path.join(base, "summary.json")]
    if not os.path.exists(paths[0]):
        paths = sorted(glob.glob(base + "-s*of*/summary.json"))
    runs = []
    for p in paths:
        try:
            with open(p, encoding="utf-8") as f:
                d = json.load(f)
        except (OSError, ValueError):
            continue
        if str(d.get("format", "")).startswith("fixpipe-deqp-summary/"):
            runs.append(d)
    if not runs:
        return None
    merged = {"counts": {}, "tests": {}, "seconds": 0.0, "started": None, "total": 0,
              "shards": len(runs), "complete": len(runs) == runs[0]["shard"][1]}
    for d in runs:
        for k, v in d["counts"].items():
            merged["counts"][k] = merged["counts"].get(k, 0) + v
        merged["tests"].update(d["tests"])
        merged["seconds"] += d.get("seconds", 0)
        merged["total"] += d.get("total", 0)
        if merged["started"] is None or d["started"] < merged["started"]:
            merged["started"] = d["started"]
    return merged


def deqp_sweep(img_dir):
    """Conformance against precision (./fixpipe deqp MODULE --sweep), where it was run."""
    out = []
    for module in ("gles2", "gles3"):
        base = os.path.join(REPO, "out", "deqp", f"sweep-{module}")
        if not os.path.exists(os.path.join(base, "sweep.md")):
            continue
        out += [f"### {module}: conformance against precision", "",
                f"`./fixpipe deqp {module} --sweep` (docs/deqp.md).", ""]
        with open(os.path.join(base, "sweep.md"), encoding="utf-8") as f:
            out += f.read().rstrip().splitlines()
        if img_dir and os.path.exists(os.path.join(base, "sweep.png")):
            name = f"deqp-sweep-{module}.png"
            shutil.copy(os.path.join(base, "sweep.png"), os.path.join(img_dir, name))
            out += ["", f"![dEQP {module} against precision]({IMG_REL}/{name})"]
        out.append("")
    return out


def deqp_section(img_dir=None):
    """The Khronos suite's counts per module and list on the three drivers."""
    runs = sorted({tuple(os.path.basename(os.path.dirname(p)).split("-", 2)[1:])
                   for p in glob.glob(os.path.join(REPO, "out", "deqp", "*-gles*-*",
                                                   "summary.json"))})
    # the named lists (and their fractions), not ad-hoc case files
    runs = sorted({(m, re.sub(r"-s\d+of\d+$", "", lst)) for m, lst in runs
                   if re.match(r"(mustpass|all)(-f\d+)?(-s\d+of\d+)?$", lst)})
    out = ["## dEQP (Khronos GL ES conformance)", ""]
    if not runs:
        return out + ["No dEQP summaries in `out/deqp/` yet: `./fixpipe deqp gles2 --driver D` "
                      "for each driver (docs/deqp.md).", ""]
    out += ["`./fixpipe deqp MODULE --list LIST --driver D` (docs/deqp.md); *pass* counts "
            "QualityWarning and CompatibilityWarning as dEQP's own summary does.", "",
            "| module | list | driver | cases | pass | fail | crash | timeout | not supported "
            "| fixpipe fails, driver passes | run |",
            "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---|"]
    for module, lst in runs:
        sums = {d: read_deqp(d, module, lst) for d in DRIVERS}
        fx = sums["fixpipe"]
        for d in DRIVERS:
            s = sums[d]
            if not s:
                out.append(f"| {module} | {lst} | {d} | – | – | – | – | – | – | – | not run |")
                continue
            c = s["counts"]
            only = "–"
            if fx and d != "fixpipe":
                only = str(sum(1 for t, r in fx["tests"].items()
                               if r["result"] in FAILING
                               and s["tests"].get(t, {}).get("result") in ("pass", "warn",
                                                                            "flake")))
            when = (s["started"] or "?").replace("T", " ").rstrip("Z")
            out.append(f"| {module} | {lst} | {d} | {s['total']} |"
                       f" {c.get('pass', 0) + c.get('warn', 0) + c.get('flake', 0)} |"
                       f" {c.get('fail', 0)} | {c.get('crash', 0)} | {c.get('timeout', 0)} |"
                       f" {c.get('notsupported', 0)} | {only} | {when}, {s['seconds']:.0f} s"
                       f"{'' if s['complete'] else ' (shards missing)'} |")
    return out + [""] + deqp_sweep(img_dir)


# ------------------------------------------------------------------ traces
def fmt_psnr(p):
    return "∞" if p is None or (isinstance(p, float) and math.isinf(p)) else f"{p:.1f}"


def read_traces():
    order = []
    try:
        with open(os.path.join(REPO, "traces", "list.txt"), encoding="utf-8") as f:
            order = [ln.split()[0] for ln in f if ln.strip() and not ln.startswith("#")]
    except OSError:
        pass
    res = []
    for name in order:
        p = os.path.join(REPO, "out", "traces", name, "result.json")
        try:
            with open(p, encoding="utf-8") as f:
                res.append(json.load(f))
        except (OSError, ValueError):
            res.append({"name": name, "missing": True})
    return res


def heatmap(name, driver, frame, img_dir):
    """Copies (or makes) the heat map of one frame into docs/img/conformance/."""
    tdir = os.path.join(REPO, "out", "traces", name)
    src = os.path.join(tdir, f"{driver}-vs-llvmpipe-{frame}.heat.png")
    dst_name = f"{name}-{driver}-{frame.lstrip('0') or '0'}.png"
    dst = os.path.join(img_dir, dst_name)
    if not os.path.exists(src):
        tool = os.path.join(REPO, "build", "std", "tools", "fp-compare")
        a = os.path.join(tdir, driver, frame + ".png")
        b = os.path.join(tdir, "llvmpipe", frame + ".png")
        if not (os.path.exists(a) and os.path.exists(b) and os.access(tool, os.X_OK)):
            return None
        subprocess.run([tool, a, b, "--heatmap", dst], capture_output=True)
    else:
        shutil.copyfile(src, dst)
    return f"{IMG_REL}/{dst_name}" if os.path.exists(dst) else None


def trace_section(img_dir):
    traces = read_traces()
    out = ["## Traces: real programs, frame by frame", ""]
    done = [t for t in traces if not t.get("missing")]
    if not done:
        return out + ["No trace results in `out/traces/`: run `./fixpipe trace`.", ""]
    out += ["Every frame of each trace (traces/list.txt: glmark2-es2 2023.01 scenes at "
            "320×240, es2gears, the project's demo) replayed with `eglretrace` through each "
            "driver and compared with llvmpipe's (tools/fp-compare). Figures are the **worst "
            "frame** of the trace for each (they may come from different frames): share of "
            "pixels differing at all, share off by more than 8 LSB, largest error, mean error "
            "(RGB, 0–255), PSNR (dB, ∞ = identical). *Replay* is the wall time of the whole "
            "`eglretrace` process (start-up, every frame, snapshots written): a figure, not a "
            "test. *Limit* is the verdict against traces/thresholds.txt.", "",
            "| trace | frames | driver | diff % | >8 LSB % | max | mean | PSNR | replay s | limit |",
            "|---|---:|---|---:|---:|---:|---:|---:|---:|---|"]
    totals = {d: 0.0 for d in DRIVERS}
    all_frames = []
    crashes = []
    for t in traces:
        if t.get("missing"):
            out.append(f"| {t['name']} | – | – | not run | | | | | | |")
            continue
        for d in ("llvmpipe",) + TESTED:
            r = t["drivers"].get(d)
            if not r:
                continue
            totals[d] += r.get("wall_s") or 0
            first = f"{t['name']} | {t['frames']}" if d == "llvmpipe" else " | "
            if d == "llvmpipe":
                out.append(f"| {first} | llvmpipe | *reference* | | | | | "
                           f"{r.get('wall_s', 0):.2f} | |")
                continue
            w = r.get("worst")
            verdict = "ok" if r.get("verdict") == "pass" else \
                "**" + "; ".join(r.get("reasons", ["fail"])).replace("|", "/") + "**"
            if r.get("crashed"):
                crashes.append((t["name"], d, r.get("command"), r.get("rc")))
            if w:
                out.append(f"| {first} | {d} | {w['diff_percent']:.3f} | {w['over8_percent']:.3f}"
                           f" | {w['max_err']} | {w['mean_err']:.4f} | {fmt_psnr(w['psnr'])} |"
                           f" {r.get('wall_s', 0):.2f} | {verdict} |")
            else:
                out.append(f"| {first} | {d} | – | – | – | – | – | {r.get('wall_s', 0):.2f} |"
                           f" {verdict} |")
            for fr in r.get("frames", []):
                all_frames.append((t["name"], d, fr))
    out.append("")
    out.append("Replay wall time over all traces: " + ", ".join(
        f"{d} {totals[d]:.1f} s" for d in DRIVERS) + ".")
    out.append("")
    if crashes:
        out += ["**Crashes** (bugs):", ""]
        for name, d, cmd, rc in crashes:
            out.append(f"- {name} on {d}: exit {rc}: `{cmd}`")
        out.append("")

    # The worst frames of fixpipe, each beside softpipe's figures for the same frame.
    fx = [(n, fr) for n, d, fr in all_frames if d == "fixpipe"]
    sp = {(n, fr["frame"]): fr for n, d, fr in all_frames if d == "softpipe"}
    fx.sort(key=lambda x: (x[1]["psnr"], -x[1]["diff_pixels"]))
    out += ["### Worst frames of fixpipe", "",
            f"The {WORST_ROWS} frames with the lowest PSNR against llvmpipe (one per scene), "
            "with softpipe's "
            "figures for the same frame: where the two agree, the difference is not the "
            "rasterizer model's (shader arithmetic: llvmpipe compiles GLSL with LLVM, softpipe "
            "and fixpipe run it through TGSI). Heat maps: black identical, blue 1 LSB, green "
            "~16, red ~150, white 255 (docs/demo.md).", "",
            "| trace | frame | fixpipe diff % / max / PSNR | softpipe diff % / max / PSNR |"
            " fixpipe heat map |",
            "|---|---:|---|---|---|"]
    shown = 0
    per_trace = {}
    for name, fr in fx:
        if shown >= WORST_ROWS or fr["diff_pixels"] == 0:
            break
        # One row per scene (glmark2-loop-*, ...): its variants look alike.
        scene = "-".join(name.split("-")[:2])
        if per_trace.get(scene):
            continue
        per_trace[scene] = 1
        s = sp.get((name, fr["frame"]))
        hf = heatmap(name, "fixpipe", fr["frame"], img_dir)
        sfig = (f"{s['diff_percent']:.2f} / {s['max_err']} / {fmt_psnr(s['psnr'])}"
                if s else "–")
        img = lambda p: f"![]({p})" if p else "–"  # noqa: E731
        out.append(f"| {name} | {fr['frame'].lstrip('0')} | {fr['diff_percent']:.2f} / "
                   f"{fr['max_err']} / {fmt_psnr(fr['psnr'])} | {sfig} | {img(hf)} |")
        shown += 1
    out.append("")

    # Where fixpipe is clearly further from llvmpipe than softpipe is: the model's share.
    gap = []
    for name, fr in fx:
        s = sp.get((name, fr["frame"]))
        if not s or fr["diff_pixels"] == 0:
            continue
        g = (s["psnr"] if not math.isinf(s["psnr"]) else 99) - fr["psnr"]
        if g >= 1.0 or fr["over8_pixels"] > 2 * s["over8_pixels"] + 20:
            gap.append((g, name, fr, s))
    gap.sort(key=lambda x: -x[0])
    out += ["### Where fixpipe is further from llvmpipe than softpipe", "",
            "Frames where fixpipe's PSNR is at least 1 dB below softpipe's, or fixpipe has "
            "clearly more pixels off by more than 8 LSB: differences the model itself makes "
            "(fill rule, fixed-point walks, the modeled formats and texture unit).", ""]
    if not gap:
        out += ["None.", ""]
    else:
        out += ["| trace | frame | fixpipe: diff % / >8 LSB % / PSNR | softpipe: diff % / >8 LSB % / PSNR |"
                " fixpipe heat map |", "|---|---:|---|---|---|"]
        seen = set()
        for g, name, fr, s in gap:
            if name in seen:
                continue
            seen.add(name)
            hf = heatmap(name, "fixpipe", fr["frame"], img_dir) if len(seen) <= 6 else None
            out.append(f"| {name} | {fr['frame'].lstrip('0')} | {fr['diff_percent']:.2f} / "
                       f"{fr['over8_percent']:.3f} / {fmt_psnr(fr['psnr'])} | "
                       f"{s['diff_percent']:.2f} / {s['over8_percent']:.3f} / "
                       f"{fmt_psnr(s['psnr'])} | {'![](' + hf + ')' if hf else ''} |")
        out.append("")
    return out


CARRIED = ("*Carried over from the previous report: no dEQP summaries were in `out/deqp/` "
           "when this page was generated; each run keeps its own date.*")


def previous_deqp(dest, img_dir):
    """The dEQP section of the page at dest (from its heading to the next one) and the
    pictures it shows, or (None, {}) when it has no runs to carry."""
    try:
        text = open(dest, encoding="utf-8").read()
    except OSError:
        return None, {}
    m = re.search(r"^## dEQP.*?(?=^## )", text, re.M | re.S)
    if not m or "No dEQP summaries" in m.group(0):
        return None, {}
    lines = m.group(0).rstrip("\n").split("\n") + [""]
    if CARRIED not in lines:
        lines[2:2] = [CARRIED, ""]
    imgs = {}
    for name in re.findall(r"img/conformance/([\w.-]+\.png)", m.group(0)):
        try:
            imgs[name] = open(os.path.join(img_dir, name), "rb").read()
        except OSError:
            pass
    return lines, imgs


def main(argv):
    ap = argparse.ArgumentParser(
        prog="fp-report.py",
        description="writes docs/conformance.md from the results already on disk")
    ap.add_argument("--out", default=os.path.join(REPO, "docs", "conformance.md"),
                    help="the page to write (default docs/conformance.md); its images go "
                         "beside it in img/conformance/")
    ap.add_argument("--lists", action="store_true",
                    help="print the piglit list names (piglit-lists/*.txt) and exit")
    ap.add_argument("--deqp", action="store_true",
                    help="print the dEQP section alone (out/deqp/*/summary.json) and exit")
    args = ap.parse_args(argv)
    if args.lists:
        print("\n".join(list_names()))
        return 0
    if args.deqp:
        print("\n".join(deqp_section()))
        return 0
    dest = args.out
    img_dir = os.path.join(os.path.dirname(dest), IMG_REL)
    # A dEQP run takes hours, and its summaries may not be on this disk: the previous
    # page's section, with its runs' dates and pictures, stands until new ones are.
    old_deqp, old_imgs = previous_deqp(dest, img_dir)
    shutil.rmtree(img_dir, ignore_errors=True)
    os.makedirs(img_dir)
    mesa = ""
    try:
        m = re.search(r"^MESA_VERSION=(\S+)", open(os.path.join(REPO, "mesa", "pin")).read(), re.M)
        mesa = m.group(1) if m else ""
    except OSError:
        pass
    lines = ["# Conformance: fixpipe against llvmpipe and softpipe", "",
             "<!-- Generated by `./fixpipe report` (tools/fp-report.py): do not edit by hand. -->",
             "",
             f"Generated {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())} on "
             f"{platform.node() or 'this machine'} ({os.cpu_count()} cores), "
             f"{('Mesa ' + mesa + ', ') if mesa else ''}"
             "fixpipe and softpipe from our Mesa build, llvmpipe from Debian's Mesa 22.3.6 "
             "(the reference). Regenerate with `./fixpipe report` (the trace run, about a "
             "minute, then this page from the piglit summaries on disk); `./fixpipe report "
             "--piglit` also runs every piglit list on the three drivers first (long).", ""]
    lines += piglit_section()
    deqp = deqp_section(img_dir)
    if deqp[2].startswith("No dEQP summaries") and old_deqp:
        deqp = old_deqp
        for name, data in old_imgs.items():
            with open(os.path.join(img_dir, name), "wb") as f:
                f.write(data)
    lines += deqp
    lines += trace_section(img_dir)
    with open(dest, "w", encoding="utf-8") as f:
        f.write("\n".join(lines).rstrip() + "\n")
    n = len(os.listdir(img_dir))
    size = sum(os.path.getsize(os.path.join(img_dir, x)) for x in os.listdir(img_dir))
    print(f"fp-report: wrote {os.path.relpath(dest, REPO)} and {n} images "
          f"({size // 1024} KiB) in {os.path.relpath(img_dir, REPO)}/")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
