#!/usr/bin/env python3
"""Benchmark povtrace against POV-Ray 3.7 (and optionally the Embree-3 ceiling) on the same scene files.

    python3 bench/run_bench.py                    # default suite: every render scene except the 1M-triangle mesh {}
    python3 bench/run_bench.py --quick            # small subset (a few minutes)
    python3 bench/run_bench.py --full --embree    # everything, with the Embree ceiling side by side
    python3 bench/run_bench.py --only showcase grid_100 --reps 1 --width 320 --height 240

Options: --reps N (5), --width/--height (640x480), --threads N (2), --only NAME..., --quick, --full, --list,
--povtrace PATH (build/povtrace), --povdiff PATH (next to povtrace), --povray PATH (povray), --timeout S per run
(900), --results DIR (bench/results), --keep DIR, --embree, --embree-src DIR, --embree-build DIR, --label TEXT,
--no-plots, --replot (redraw the plots from an existing latest.csv).

Render suite (each also as NAME_aa, rendered with `+A0.3 +R3 -J` instead of `-A` by both renderers; no jitter, so the
images are comparable pixel for pixel):
  showcase                      scenes/showcase.pov unchanged
  grid_100, grid_10000, grid_100000
                                N spheres on a square grid over a plane (constant image coverage), two lights
  glass                         glass, mirror and diffuse spheres and a box over a checker floor, max_trace_level 5
  glass_anchor                  the perf-anchor's glass scene (has an Embree twin; `glass` has none)
  mesh_T, mesh2_T               the perf-anchor's bumpy torus, T = 10000, 99856, 1000000 triangles, written as
                                `mesh { triangle … }` and as `mesh2 {}`; identical to /work/shared/perf-anchor's files
Only with --only: mesh_1m (legacy: a 1M-triangle mesh2 height field) and the parse-only scenes parse_while,
parse_macro, parse_objects, parse_declares (always rendered at 32x24 so that parsing dominates).
The default run leaves out mesh_1000000 and mesh_1000000_aa: POV-Ray's `mesh {}` parse is quadratic (about 80 s a
run for 1M triangles); --full includes them.

For every scene, povtrace and povray each run --reps times, interleaved (the order flips every repetition), with the
same switches `-D -A +W<w> +H<h> +FE +WT<threads>`; povtrace also gets `--stats=FILE.json`. Recorded per run:
whole-process wall time, POV-Ray's reported parse/bounding/trace times and povtrace's parse_s/build_s/render_s/
total_s/rays (from the stats JSON), and peak resident memory. After a run times out, the same program's remaining
repetitions of that scene are skipped (the table says so). The two images of the last repetition are compared
with povdiff (PSNR). With --embree, /work/shared/perf-anchor/embree_bench is built into build/bench-embree/ and run
once per scene that has a .scn twin (its own --reps repetitions inside one process).

Results in --results: latest.csv (one row per scene), latest_runs.csv (one row per run), latest.md (Markdown
tables) and, through gnuplot, latest_times.png, latest_ratios.png and latest_scaling.png. Ratios are
POV-Ray / povtrace (> 1: povtrace is faster) and povtrace / Embree, POV-Ray / Embree (> 1: slower than the ceiling).
A failure is recorded in the tables and the run continues.
"""
import argparse
import csv
import json
import math
import os
import shutil
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_scenes import (SCENES, base_scene, grid_scene_text, glass_scene_text,  # noqa: E402,F401 (re-exported)
                          parse_scene_text, write_scene)
from bench_tools import (REPO, cpu_name, ensure_gnuplot, ensure_packages, gnuplot_string,  # noqa: E402
                         load_average, memory_method, now_text, parse_povray_times, povray_version, repo_commit,
                         run_gnuplot, run_measured, tail)

GRID_SIZES = (100, 10000, 100000)
PARSE_SCENES = ("parse_while", "parse_macro", "parse_objects", "parse_declares")
PARSE_SIZE = (32, 24)   # parse-only scenes: a tiny image, so that the parse dominates
LEGACY_SCENES = ("mesh_1m",)
MESH_SIZES = (10000, 99856, 1000000)
SUITE_BASES = (["showcase"] + [f"grid_{n}" for n in GRID_SIZES] + ["glass", "glass_anchor"] +
               [f"{fmt}_{t}" for t in MESH_SIZES for fmt in ("mesh", "mesh2")])
SUITE = [v for b in SUITE_BASES for v in (b, b + "_aa")]
SLOW = ("mesh_1000000", "mesh_1000000_aa")
DEFAULT = [n for n in SUITE if n not in SLOW]
QUICK = [v for b in ("showcase", "grid_10000", "glass", "mesh_10000", "mesh2_10000") for v in (b, b + "_aa")]
SCENE_NAMES = SUITE + list(LEGACY_SCENES) + list(PARSE_SCENES)
AA_SWITCHES = ["+A0.3", "+R3", "-J"]
EMBREE_AA = ["--aa", "0.3", "--aa-depth", "3"]   # embree_bench's method-1-like AA at the same threshold and depth
EMBREE_SRC = "/work/shared/perf-anchor"
EMBREE_PACKAGES = ["libembree-dev", "g++", "make"]


def quality_switches(name):
    """Antialiasing switches: -A, or the AA settings for the *_aa variants."""
    return AA_SWITCHES if name.endswith("_aa") else ["-A"]


def image_size(name, args):
    """(width, height) for a scene: --width/--height, except for the parse-only scenes."""
    return PARSE_SIZE if name in PARSE_SCENES else (args.width, args.height)


# ---------------------------------------------------------------------------------------------------------------
# Running one measurement


def failed_run(tool, error):
    return {"tool": tool, "ok": False, "rc": None, "wall_s": None, "peak_kb": None, "parse_s": None,
            "build_s": None, "render_s": None, "total_s": None, "rays": None, "error": error}


def run_povray(args, scene, image, cwd, scratch, size, quality):
    command = [args.povray, "-D"] + quality + [f"+W{size[0]}", f"+H{size[1]}", "+FE", f"+WT{args.threads}",
                                               f"+O{image}", scene]
    if os.path.exists(image):
        os.remove(image)
    result = run_measured(command, cwd, args.timeout, scratch)
    times = parse_povray_times(result["output"])
    ok = result["rc"] == 0 and times["trace_s"] is not None and os.path.exists(image)
    error = None
    if not ok:
        error = tail(result["output"])
    return {"tool": "povray", "ok": ok, "rc": result["rc"], "wall_s": result["wall_s"],
            "peak_kb": result["peak_kb"], "parse_s": times["parse_s"], "build_s": times["bounding_s"],
            "render_s": times["trace_s"], "total_s": None, "rays": None, "error": error}


def run_povtrace(args, scene, image, stats, cwd, scratch, size, quality):
    for path in (stats, image):
        if os.path.exists(path):
            os.remove(path)
    command = [args.povtrace, "-D"] + quality + [f"+W{size[0]}", f"+H{size[1]}", "+FE", f"+WT{args.threads}",
                                                 f"+O{image}", f"--stats={stats}", scene]
    if not os.access(args.povtrace, os.X_OK):
        return failed_run("povtrace", f"{args.povtrace} not found or not executable")
    result = run_measured(command, cwd, args.timeout, scratch)
    data, error = {}, None
    try:
        with open(stats) as f:
            data = json.load(f)
    except (OSError, ValueError) as e:
        error = f"no readable stats JSON ({e})"
    ok = result["rc"] == 0 and error is None and os.path.exists(image)
    if result["rc"] != 0:
        error = "timed out" if result["rc"] is None else f"exit status {result['rc']}"
    elif not ok and error is None:
        error = "no output image"
    row = {"tool": "povtrace", "ok": ok, "rc": result["rc"], "wall_s": result["wall_s"],
           "peak_kb": result["peak_kb"], "error": None if ok else "; ".join(filter(None, [error, tail(result["output"])]))}
    for key in ("parse_s", "build_s", "render_s", "total_s", "rays"):
        value = data.get(key) if isinstance(data, dict) else None
        row[key] = value if isinstance(value, (int, float)) else None
    return row


def compare_images(args, ours, theirs):
    """Runs povdiff; returns (psnr, verdict, message). psnr is a float (inf allowed) or None."""
    if not (os.path.exists(ours) and os.path.exists(theirs)):
        return None, "n/a", "missing image"
    if not os.access(args.povdiff, os.X_OK):
        return None, "n/a", f"{args.povdiff} not found"
    proc = subprocess.run([args.povdiff, ours, theirs], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          text=True, errors="replace")
    lines = [line for line in proc.stdout.splitlines() if line.startswith("povdiff:")]
    if not lines:
        return None, "n/a", tail(proc.stdout)
    fields = dict(item.split("=", 1) for item in lines[-1].split()[1:] if "=" in item)
    try:
        psnr = float(fields.get("psnr", "nan"))
    except ValueError:
        psnr = None
    return psnr, fields.get("verdict", "n/a"), lines[-1]


def run_repetitions(args, name, scene, work):
    """povtrace and povray alternately, --reps times each; a program that timed out is not run again on this
    scene. Returns (runs, povtrace image, povray image)."""
    ours = os.path.join(work, f"{name}.povtrace.exr")
    theirs = os.path.join(work, f"{name}.povray.exr")
    stats = os.path.join(work, f"{name}.stats.json")
    size, quality = image_size(name, args), quality_switches(name)
    runs, timed_out = [], set()
    for rep in range(args.reps):
        order = ("povtrace", "povray") if rep % 2 == 0 else ("povray", "povtrace")
        for tool in order:
            if tool in timed_out:
                continue
            if tool == "povtrace":
                r = run_povtrace(args, scene, ours, stats, work, work, size, quality)
            else:
                r = run_povray(args, scene, theirs, work, work, size, quality)
            r.update(scene=name, rep=rep + 1)
            runs.append(r)
            if r["rc"] is None and r["wall_s"] is not None:
                timed_out.add(tool)
                r["error"] = f"timed out after {args.timeout:g} s; later repetitions skipped | " + (r["error"] or "")
            state = "ok" if r["ok"] else "FAILED: " + (r["error"] or "")
            print(f"  {name:18s} rep {rep + 1}/{args.reps} {tool:8s} wall {fmt(r['wall_s'])} s"
                  f"  parse {fmt(r['parse_s'])} s  render {fmt(r['render_s'])} s"
                  f"  peak {fmt(r['peak_kb'], 0)} kB  {state}", flush=True)
    return runs, ours, theirs


# ---------------------------------------------------------------------------------------------------------------
# The Embree ceiling


def build_embree(args):
    """Builds embree_bench from --embree-src into --embree-build with the anchor's own Makefile (make -f … VPATH=…,
    so its compiler flags are used unchanged). Returns (path or None, error text)."""
    source = os.path.join(args.embree_src, "embree_bench.cpp")
    makefile = os.path.join(args.embree_src, "Makefile")
    if not (os.path.exists(source) and os.path.exists(makefile)):
        return None, f"no embree_bench.cpp and Makefile in {args.embree_src}"
    error = ensure_packages(EMBREE_PACKAGES, "--embree")
    if error:
        return None, error
    os.makedirs(args.embree_build, exist_ok=True)
    # The Makefile sets CXX and CXXFLAGS with ?=: a CXXFLAGS=-O0 in the caller's environment would slow the ceiling.
    env = {k: v for k, v in os.environ.items() if k not in ("CXX", "CXXFLAGS")}
    proc = subprocess.run(["make", "-C", args.embree_build, "-f", makefile, f"VPATH={args.embree_src}",
                           "embree_bench"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                          errors="replace", env=env)
    binary = os.path.join(args.embree_build, "embree_bench")
    if proc.returncode != 0 or not os.access(binary, os.X_OK):
        return None, "building embree_bench failed: " + tail(proc.stdout, 6)
    return binary, ""


def parse_embree_result(output):
    """embree_bench prints one `RESULT key=value …` line; returns its fields (numbers as floats) or None."""
    line = next((line for line in output.splitlines() if line.startswith("RESULT ")), None)
    if line is None:
        return None
    fields = {}
    for item in line.split()[1:]:
        key, _, value = item.partition("=")
        try:
            fields[key] = float(value)
        except ValueError:
            fields[key] = value
    return fields


def run_embree(args, name, scn, work):
    """One embree_bench process: --reps renders after one load and build. Returns a dict of embree_* values."""
    width, height = image_size(name, args)
    image = os.path.join(work, f"{name}.embree.ppm")
    command = [args.embree_bin, scn, "--threads", str(args.threads), "--width", str(width), "--height", str(height),
               "--reps", str(args.reps), "--out", image] + (EMBREE_AA if name.endswith("_aa") else [])
    result = run_measured(command, work, args.timeout, work)
    fields = parse_embree_result(result["output"]) if result["rc"] == 0 else None
    row = {"embree_ok": fields is not None, "embree_wall_s": result["wall_s"],
           "embree_peak_mb": result["peak_kb"] / 1024 if result["peak_kb"] else None,
           "embree_load_s": None, "embree_build_s": None, "embree_render_s_min": None,
           "embree_render_s_median": None, "embree_rays": None, "embree_error": ""}
    if fields is None:
        row["embree_error"] = ("timed out; " if result["rc"] is None else "") + tail(result["output"])
        return row, None
    row.update(embree_load_s=fields.get("load_s"), embree_build_s=fields.get("build_s"),
               embree_render_s_min=fields.get("render_min_s"), embree_render_s_median=fields.get("render_med_s"),
               embree_rays=fields.get("rays"))
    return row, image


# ---------------------------------------------------------------------------------------------------------------
# Summary


def stat(values, fn):
    values = [v for v in values if v is not None]
    return fn(values) if values else None


def ratio(a, b):
    return a / b if a is not None and b not in (None, 0) else None


def summarize(name, runs, psnr, verdict, args):
    pt = [r for r in runs if r["tool"] == "povtrace"]
    pr = [r for r in runs if r["tool"] == "povray"]
    pt_ok = [r for r in pt if r["ok"]]
    pr_ok = [r for r in pr if r["ok"]]
    width, height = image_size(name, args)
    spec = SCENES[base_scene(name)]
    row = {"scene": name, "family": spec.family, "primitives": spec.primitives,
           "antialias": " ".join(quality_switches(name)), "width": width, "height": height,
           "threads": args.threads, "reps": args.reps,
           "povtrace_ok": f"{len(pt_ok)}/{len(pt)}", "povray_ok": f"{len(pr_ok)}/{len(pr)}"}
    for tool, ok in (("povtrace", pt_ok), ("povray", pr_ok)):
        for key in ("wall_s", "render_s"):
            row[f"{tool}_{key}_min"] = stat([r[key] for r in ok], min)
            row[f"{tool}_{key}_median"] = stat([r[key] for r in ok], statistics.median)
        row[f"{tool}_parse_s_median"] = stat([r["parse_s"] for r in ok], statistics.median)
        row[f"{tool}_build_s_median"] = stat([r["build_s"] for r in ok], statistics.median)
        row[f"{tool}_peak_mb"] = stat([r["peak_kb"] / 1024 if r["peak_kb"] else None for r in ok], max)
    row["povtrace_rays"] = stat([r["rays"] for r in pt_ok], max)
    for key in ("wall", "render"):
        for which in ("median", "min"):
            row[f"ratio_{key}_{which}"] = ratio(row[f"povray_{key}_s_{which}"], row[f"povtrace_{key}_s_{which}"])
    row["ratio_parse_median"] = ratio(row["povray_parse_s_median"], row["povtrace_parse_s_median"])
    row["ratio_build_median"] = ratio(row["povray_build_s_median"], row["povtrace_build_s_median"])
    row["psnr_db"] = psnr
    row["povdiff_verdict"] = verdict
    errors = [r["error"] for r in runs if r["error"]]
    row["errors"] = errors[0] if errors else ""
    return row


EMBREE_FIELDS = ["embree_ok", "embree_wall_s", "embree_peak_mb", "embree_load_s", "embree_build_s",
                 "embree_render_s_min", "embree_render_s_median", "embree_rays", "embree_psnr_db",
                 "povtrace_over_embree_render_median", "povray_over_embree_render_median", "embree_error"]


def add_embree(row, embree):
    """Adds the embree_* columns (None/"" when Embree was not run or the scene has no twin)."""
    for key in EMBREE_FIELDS:
        row[key] = embree.get(key, "" if key == "embree_error" else None)
    row["povtrace_over_embree_render_median"] = ratio(row["povtrace_render_s_median"],
                                                      row["embree_render_s_median"])
    row["povray_over_embree_render_median"] = ratio(row["povray_render_s_median"], row["embree_render_s_median"])


def fmt(value, digits=3):
    if value is None or value == "":
        return "–"
    if isinstance(value, float):
        if math.isinf(value):
            return "inf"
        if math.isnan(value):
            return "nan"
        return f"{value:.{digits}f}"
    return str(value)


MAIN_COLUMNS = [
    ("scene", "scene", 0), ("povtrace_ok", "povtrace ok", 0), ("povray_ok", "povray ok", 0),
    ("povtrace_wall_s_min", "povtrace wall min s", 3), ("povtrace_wall_s_median", "povtrace wall med s", 3),
    ("povray_wall_s_min", "povray wall min s", 3), ("povray_wall_s_median", "povray wall med s", 3),
    ("ratio_wall_median", "wall ratio (med)", 2),
    ("povtrace_render_s_min", "povtrace render min s", 3), ("povtrace_render_s_median", "povtrace render med s", 3),
    ("povray_render_s_min", "povray trace min s", 3), ("povray_render_s_median", "povray trace med s", 3),
    ("ratio_render_median", "render ratio (med)", 2), ("ratio_render_min", "render ratio (min)", 2),
    ("povtrace_parse_s_median", "povtrace parse med s", 3), ("povray_parse_s_median", "povray parse med s", 3),
    ("ratio_parse_median", "parse ratio (med)", 2),
    ("povtrace_build_s_median", "povtrace build med s", 3), ("povray_build_s_median", "povray bounding med s", 3),
    ("povtrace_peak_mb", "povtrace peak MB", 1), ("povray_peak_mb", "povray peak MB", 1),
    ("psnr_db", "PSNR dB", 1)]

EMBREE_COLUMNS = [
    ("scene", "scene", 0), ("embree_build_s", "Embree build s", 3),
    ("embree_render_s_min", "Embree render min s", 4), ("embree_render_s_median", "Embree render med s", 4),
    ("povtrace_render_s_median", "povtrace render med s", 3), ("povray_render_s_median", "povray trace med s", 3),
    ("povtrace_over_embree_render_median", "povtrace ÷ Embree (med)", 2),
    ("povray_over_embree_render_median", "POV-Ray ÷ Embree (med)", 2),
    ("embree_peak_mb", "Embree peak MB", 1), ("embree_psnr_db", "Embree vs POV-Ray PSNR dB", 1)]


def markdown_table(rows, cols):
    lines = ["| " + " | ".join(c[1] for c in cols) + " |", "|" + "|".join("---" for _ in cols) + "|"]
    for row in rows:
        lines.append("| " + " | ".join(fmt(row.get(c[0]), c[2]) for c in cols) + " |")
    return "\n".join(lines) + "\n"


def write_markdown(path, rows, header_lines, args, plots, plot_note):
    with open(path, "w") as f:
        title = "# povtrace vs POV-Ray benchmark" + (f" ({args.label})" if args.label else "")
        f.write(title + "\n\n")
        for line in header_lines:
            f.write(f"- {line}\n")
        f.write("\nRatios are POV-Ray / povtrace (> 1: povtrace is faster). \"render\" compares POV-Ray's reported "
                "Trace Time with povtrace's render_s; \"parse\" POV-Ray's Parse Time with povtrace's parse_s; "
                "\"bounding\" is POV-Ray's Bounding Time next to povtrace's BVH build_s; \"wall\" is the whole "
                "process. PSNR compares the two images of the last repetition (povdiff, linear EXR). The parse_* "
                f"scenes are rendered at {PARSE_SIZE[0]}x{PARSE_SIZE[1]} whatever the image size.\n\n")
        f.write(markdown_table(rows, MAIN_COLUMNS))
        if args.embree:
            f.write("\n## Against the Embree-3 ceiling\n\n"
                    f"`embree_bench` from {args.embree_src} ({args.embree_status}) on each scene's .scn twin, "
                    f"--threads {args.threads}, {args.reps} renders inside one process after one load and build; "
                    "the *_aa scenes use its method-1-like AA (`--aa 0.3 --aa-depth 3`: R x R samples without "
                    "POV-Ray's extra centre sample, 4-neighbour test). Ratios are render time ÷ Embree render time "
                    "(> 1: slower than the ceiling). Embree's PSNR against POV-Ray's image shows how close its "
                    "simplified shading is (8-bit PPM against linear EXR).\n\n")
            twins = [r for r in rows if r.get("embree_ok") is not None or r.get("embree_error")]
            f.write(markdown_table(twins, EMBREE_COLUMNS))
            missing = [r for r in rows if r not in twins]
            if missing:
                f.write("\nNo Embree run: " + "; ".join(
                    f"{r['scene']} ({SCENES[base_scene(r['scene'])].no_twin or 'not run'})" for r in missing) + ".\n")
        if plots:
            f.write("\n## Plots\n\n")
            for png in plots:
                f.write(f"![{png}]({png})\n\n")
        if plot_note:
            f.write(f"\nPlots: {plot_note}\n")
        failures = [r for r in rows if r["errors"] or r.get("embree_error")]
        if failures:
            f.write("\n## Failures\n\n")
            for r in failures:
                for text in (r["errors"], r.get("embree_error")):
                    if text:
                        f.write(f"- {r['scene']}: {text}\n")


def environment_lines(args):
    return [f"date: {now_text()}; load average at start: {load_average()}",
            f"machine: {cpu_name()}, {os.cpu_count()} logical CPUs",
            f"POV-Ray: {povray_version(args.povray)}; povtrace: {args.povtrace} (repository commit {repo_commit()})",
            f"image {args.width}x{args.height} (parse_* scenes {PARSE_SIZE[0]}x{PARSE_SIZE[1]}), -A (*_aa scenes: "
            f"{' '.join(AA_SWITCHES)}), +FE, +WT{args.threads} for both, {args.reps} repetitions each, "
            f"timeout {args.timeout:g} s a run",
            f"peak memory: {memory_method()}"]


# ---------------------------------------------------------------------------------------------------------------
# Plots (gnuplot, PNG)


def dat(value):
    return "NaN" if value is None or (isinstance(value, float) and not math.isfinite(value)) else f"{value:.6g}"


def has_values(rows, key):
    return any(isinstance(r.get(key), (int, float)) and math.isfinite(r[key]) and r[key] > 0 for r in rows)


# POV-Ray reports its parse time in milliseconds: below this, a parse ratio is rounding, not a measurement.
MIN_PARSE_FOR_RATIO_S = 0.02


def meaningful_parse(row):
    times = [row.get("povtrace_parse_s_median"), row.get("povray_parse_s_median")]
    return all(isinstance(t, (int, float)) for t in times) and max(times) >= MIN_PARSE_FOR_RATIO_S


PT_COLOUR, PR_COLOUR, EM_COLOUR = "#d9622b", "#2b6cd9", "#3a9a3a"

# Per-scene bar panels: (title, y label, [(row key, legend, colour)]). Series without a value are left out, and a
# panel with no series at all is not drawn (gnuplot stops on a plot without valid points).
SCENE_PANELS = {
    "latest_times.png": [
        ("Render time (POV-Ray: Trace Time; povtrace: render_s)", "seconds (log)",
         [("povtrace_render_s_median", "povtrace", PT_COLOUR), ("povray_render_s_median", "POV-Ray 3.7", PR_COLOUR),
          ("embree_render_s_median", "Embree ceiling", EM_COLOUR)]),
        ("Whole-process wall time", "seconds (log)",
         [("povtrace_wall_s_median", "povtrace", PT_COLOUR), ("povray_wall_s_median", "POV-Ray 3.7", PR_COLOUR)])],
    "latest_ratios.png": [
        ("POV-Ray ÷ povtrace (> 1: povtrace is faster)", "ratio (log)",
         [("ratio_render_median", "render", PT_COLOUR), ("ratio_wall_median", "wall", "#888888"),
          ("ratio_parse_median", f"parse (where a parse takes >= {MIN_PARSE_FOR_RATIO_S:g} s)", "#7a4fb0")]),
        ("Render time ÷ Embree ceiling (> 1: slower than Embree)", "ratio (log)",
         [("povtrace_over_embree_render_median", "povtrace ÷ Embree", PT_COLOUR),
          ("povray_over_embree_render_median", "POV-Ray ÷ Embree", PR_COLOUR)])],
}
SCALING_FAMILIES = [("grid", "sphere grid", 1, 7), ("mesh", "torus mesh {}", 2, 5), ("mesh2", "torus mesh2 {}", 3, 9)]
SCALING_PANELS = [
    ("render time", "seconds (log)", [("povtrace_render_s_median", "povtrace", PT_COLOUR),
                                      ("povray_render_s_median", "POV-Ray", PR_COLOUR),
                                      ("embree_render_s_median", "Embree", EM_COLOUR)]),
    ("parse time", "seconds (log)", [("povtrace_parse_s_median", "povtrace", PT_COLOUR),
                                     ("povray_parse_s_median", "POV-Ray", PR_COLOUR)]),
    ("peak resident memory", "MB (log)", [("povtrace_peak_mb", "povtrace", PT_COLOUR),
                                          ("povray_peak_mb", "POV-Ray", PR_COLOUR),
                                          ("embree_peak_mb", "Embree", EM_COLOUR)]),
]


def scene_bars_script(png, panels, rows, data, keys, subtitle):
    """gnuplot script of clustered bars (one cluster per scene) for the panels that have data, or None."""
    drawn = []
    for title, ylabel, series in panels:
        present = [(keys.index(k) + 2, legend, colour) for k, legend, colour in series if has_values(rows, k)]
        if present:
            drawn.append((title, ylabel, present))
    if not drawn:
        return None
    width = max(900, 60 * len(rows) + 200)
    out = [f"set terminal pngcairo size {width},{450 * len(drawn) + 30}", f"set output '{png}'",
           "set termoption noenhanced", "set datafile missing 'NaN'", "set style data histograms",
           "set style histogram clustered gap 1", "set style fill solid 0.85 border -1", "set boxwidth 0.9",
           "set xtics rotate by -45 scale 0 font ',9'", "set grid ytics", "set key top left", "set logscale y",
           f"set multiplot layout {len(drawn)},1"]
    for title, ylabel, present in drawn:
        if "ratio" in ylabel:
            out.append("set arrow 1 from graph 0, first 1 to graph 1, first 1 nohead lw 2 lc rgb 'black' front")
        else:
            out.append("unset arrow 1")
        out.append(f"set title {gnuplot_string(title + chr(10) + subtitle)}")
        out.append(f"set ylabel '{ylabel}'")
        parts = []
        for i, (col, legend, colour) in enumerate(present):
            src = gnuplot_string(data) if i == 0 else "''"
            parts.append(f"{src} using {col}{':xtic(1)' if i == 0 else ''} title {gnuplot_string(legend)} "
                         f"lc rgb '{colour}'")
        out.append("plot " + ", ".join(parts))
    out.append("unset multiplot")
    return "\n".join(out) + "\n"


def scaling_script(rows, work, subtitle):
    """gnuplot script of time and memory against object count (no-AA grid and torus scenes), or None."""
    files, families = {}, []
    for fam, title, dash, point in SCALING_FAMILIES:
        series = sorted((r for r in rows if r["family"] == fam and not r["scene"].endswith("_aa")),
                        key=lambda r: r["primitives"])
        if series:
            families.append((fam, title, dash, point, series))
    if not families:
        return None
    keys = [k for _, _, series in SCALING_PANELS for k, _, _ in series]
    for fam, _, _, _, series in families:
        files[fam] = os.path.join(work, f"plot_scaling_{fam}.dat")
        with open(files[fam], "w") as f:
            f.write("# primitives " + " ".join(keys) + "\n")
            for r in series:
                f.write(" ".join([str(r["primitives"])] + [dat(r.get(k)) for k in keys]) + "\n")
    panels = []
    for title, ylabel, series in SCALING_PANELS:
        curves = []
        for fam, fam_title, dash, point, fam_rows in families:
            for k, legend, colour in series:
                if has_values(fam_rows, k):
                    curves.append(f"{gnuplot_string(files[fam])} using 1:{keys.index(k) + 2} with linespoints "
                                  f"dt {dash} pt {point} lw 2 lc rgb '{colour}' "
                                  f"title {gnuplot_string(legend + ', ' + fam_title)}")
        if curves:
            panels.append((title, ylabel, curves))
    if not panels:
        return None
    out = [f"set terminal pngcairo size {500 * len(panels)},660", "set output 'latest_scaling.png'",
           "set termoption noenhanced", "set datafile missing 'NaN'", "set logscale xy", "set grid",
           "set key below maxrows 3 font ',8'", "set offsets graph 0.05, graph 0.05",
           f"set multiplot layout 1,{len(panels)} title "
           f"{gnuplot_string('Against the number of spheres or triangles (x, log), no AA' + chr(10) + subtitle)}"]
    for title, ylabel, curves in panels:
        out += [f"set title '{title}'", f"set ylabel '{ylabel}'", "plot " + ", ".join(curves)]
    out.append("unset multiplot")
    return "\n".join(out) + "\n"


def write_plots(rows, args, work):
    """Writes latest_times.png, latest_ratios.png and (when grid or mesh scenes ran) latest_scaling.png into
    args.results. Returns (list of PNG names, note text)."""
    if args.no_plots:
        return [], "not made (--no-plots)"
    gnuplot, why = ensure_gnuplot()
    if gnuplot is None:
        return [], f"not made: {why}"
    subtitle = f"{args.width}x{args.height}, {args.threads} threads, median of {args.reps}"
    if args.label:
        subtitle += f" — {args.label}"
    keys = [k for panels in SCENE_PANELS.values() for _, _, series in panels for k, _, _ in series]
    data = os.path.join(work, "plot_scenes.dat")
    with open(data, "w") as f:
        f.write("# scene " + " ".join(keys) + "\n")
        for r in rows:
            values = {k: r.get(k) for k in keys}
            if not meaningful_parse(r):
                values["ratio_parse_median"] = None
            f.write(" ".join([r["scene"]] + [dat(values[k]) for k in keys]) + "\n")
    scripts = {png: scene_bars_script(png, panels, rows, data, keys, subtitle) for png, panels in SCENE_PANELS.items()}
    scripts["latest_scaling.png"] = scaling_script(rows, work, subtitle)
    made, errors = [], []
    for png, script in scripts.items():
        stale = os.path.join(args.results, png)
        if os.path.exists(stale):   # a plot this run does not redraw must not stay behind from an earlier run
            os.remove(stale)
        if script is None:
            continue
        script_path = os.path.join(work, png.replace(".png", ".gp"))
        with open(script_path, "w") as f:
            f.write(script)
        error = run_gnuplot(gnuplot, script_path, os.path.abspath(args.results))
        if error:
            errors.append(error)
        else:
            made.append(png)
    return made, "; ".join(errors)


# ---------------------------------------------------------------------------------------------------------------


def parse_args(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--width", type=int, default=640)
    ap.add_argument("--height", type=int, default=480)
    ap.add_argument("--threads", type=int, default=2)
    which = ap.add_mutually_exclusive_group()
    which.add_argument("--only", nargs="+", metavar="NAME", choices=SCENE_NAMES,
                       help="scenes to run (any of " + ", ".join(SCENE_NAMES) + ")")
    which.add_argument("--quick", action="store_true", help="only " + ", ".join(QUICK))
    which.add_argument("--full", action="store_true", help="the whole render suite, " + " and ".join(SLOW) +
                       " included")
    ap.add_argument("--list", action="store_true", help="print the scene names of each set and exit")
    ap.add_argument("--povtrace", default=os.path.join(REPO, "build", "povtrace"))
    ap.add_argument("--povray", default="povray")
    ap.add_argument("--povdiff", default=None, help="default: povdiff next to --povtrace")
    ap.add_argument("--timeout", type=float, default=900, help="seconds per run")
    ap.add_argument("--results", default=os.path.join(REPO, "bench", "results"))
    ap.add_argument("--keep", metavar="DIR", help="keep scenes and images in DIR instead of a temporary folder")
    ap.add_argument("--embree", action="store_true", help="also build and run the Embree-3 ceiling")
    ap.add_argument("--embree-src", default=EMBREE_SRC, help="folder with embree_bench.cpp and its Makefile")
    ap.add_argument("--embree-build", default=os.path.join(REPO, "build", "bench-embree"),
                    help="where embree_bench is built (never inside --embree-src)")
    ap.add_argument("--label", default="", help="a note for the titles of the tables and plots, e.g. 'smoke run'")
    ap.add_argument("--no-plots", action="store_true")
    ap.add_argument("--replot", action="store_true",
                    help="only redraw the plots from the latest.csv in --results (pass the same --label)")
    args = ap.parse_args(argv)
    args.povtrace = os.path.abspath(args.povtrace)
    if args.povdiff is None:
        args.povdiff = os.path.join(os.path.dirname(args.povtrace), "povdiff")
    args.povdiff = os.path.abspath(args.povdiff)
    args.embree_src = os.path.abspath(args.embree_src)
    args.embree_build = os.path.abspath(args.embree_build)
    if args.reps < 1:
        ap.error("--reps must be at least 1")
    if args.embree and os.path.commonpath([args.embree_src, args.embree_build]) == args.embree_src:
        ap.error("--embree-build must not be inside --embree-src")
    return args


def selected_names(args):
    if args.only:
        return list(dict.fromkeys(args.only))
    return QUICK if args.quick else SUITE if args.full else DEFAULT


def read_rows(path):
    """latest.csv back as summary rows: numbers as int/float, empty cells as None."""
    def value(text):
        if text == "":
            return None
        for kind in (int, float):
            try:
                return kind(text)
            except ValueError:
                pass
        return text
    with open(path, newline="") as f:
        rows = [{k: value(v) for k, v in row.items()} for row in csv.DictReader(f)]
    for row in rows:
        for key in ("scene", "povtrace_ok", "povray_ok", "errors", "embree_error"):
            if key in row:
                row[key] = "" if row[key] is None else str(row[key])
    return rows


def replot(args):
    rows = read_rows(os.path.join(args.results, "latest.csv"))
    if not rows:
        return 1
    args.width, args.height, args.threads, args.reps = (rows[0][k] for k in ("width", "height", "threads", "reps"))
    with tempfile.TemporaryDirectory(prefix="povtrace-bench-plots-") as work:
        plots, note = write_plots(rows, args, work)
    print("plots: " + ", ".join(plots) + (f"; {note}" if note else ""))
    return 0 if plots else 1


def main(argv=None):
    args = parse_args(argv)
    if args.replot:
        return replot(args)
    if args.list:
        for title, names in (("default", DEFAULT), ("--quick", QUICK), ("--full", SUITE),
                             ("--only also", list(LEGACY_SCENES) + list(PARSE_SCENES))):
            print(f"{title}: {' '.join(names)}")
        return 0
    names = selected_names(args)
    if args.keep:
        work = os.path.abspath(args.keep)
        os.makedirs(work, exist_ok=True)
    else:
        work = tempfile.mkdtemp(prefix="povtrace-bench-")
    os.makedirs(args.results, exist_ok=True)
    header = environment_lines(args)
    args.embree_bin, args.embree_status = None, ""
    if args.embree:
        args.embree_bin, error = build_embree(args)
        args.embree_status = f"built in {args.embree_build}" if args.embree_bin else f"NOT AVAILABLE: {error}"
        header.append(f"Embree ceiling: {args.embree_status}")
    if args.label:
        header.insert(0, f"label: {args.label}")
    for line in header:
        print(line)
    print(f"working folder: {work}", flush=True)

    rows, all_runs = [], []
    try:
        bases = list(dict.fromkeys(base_scene(n) for n in names))
        for base in bases:
            print(f"writing {base}.pov", flush=True)
            pov, scn = write_scene(base, work)
            for name in [n for n in names if base_scene(n) == base]:
                runs, ours, theirs = run_repetitions(args, name, os.path.basename(pov), work)
                psnr, verdict, message = compare_images(args, ours, theirs)
                row = summarize(name, runs, psnr, verdict, args)
                embree = {}
                if args.embree and scn and args.embree_bin:
                    embree, image = run_embree(args, name, scn, work)
                    if image:
                        embree["embree_psnr_db"] = compare_images(args, image, theirs)[0]
                elif args.embree and scn:
                    embree = {"embree_error": args.embree_status}
                add_embree(row, embree)
                rows.append(row)
                all_runs.extend(runs)
                print(f"{name}: render ratio (median) {fmt(row['ratio_render_median'], 2)}, parse ratio (median) "
                      f"{fmt(row['ratio_parse_median'], 2)}, wall ratio (median) {fmt(row['ratio_wall_median'], 2)}, "
                      f"PSNR {fmt(psnr, 1)} dB ({message})"
                      + (f", povtrace/Embree {fmt(row['povtrace_over_embree_render_median'], 2)}"
                         f" {row['embree_error']}" if args.embree else ""), flush=True)
            if not args.keep:   # the 1M-triangle files are ~100 MB each
                for path in (pov, scn):
                    if path and os.path.exists(path):
                        os.remove(path)
        if not rows:
            return 1
        plots, plot_note = write_plots(rows, args, work)
    finally:
        if not args.keep:
            shutil.rmtree(work, ignore_errors=True)

    csv_path = os.path.join(args.results, "latest.csv")
    with open(csv_path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    runs_path = os.path.join(args.results, "latest_runs.csv")
    run_fields = ["scene", "rep", "tool", "ok", "rc", "wall_s", "parse_s", "build_s", "render_s", "total_s", "rays",
                  "peak_kb", "error"]
    with open(runs_path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=run_fields, extrasaction="ignore")
        w.writeheader()
        w.writerows(all_runs)
    md_path = os.path.join(args.results, "latest.md")
    write_markdown(md_path, rows, header, args, plots, plot_note)
    print()
    with open(md_path) as f:
        print(f.read())
    print(f"wrote {csv_path}, {runs_path}, {md_path}" + "".join(f", {os.path.join(args.results, p)}" for p in plots))
    return 0


if __name__ == "__main__":
    sys.exit(main())
