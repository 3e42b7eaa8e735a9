#!/usr/bin/env python3
"""Run time against error of antialiasing, povtrace and POV-Ray 3.7 at the same settings.

    python3 bench/pareto.py                                   # showcase and glass at 240x180, 3 repetitions
    python3 bench/pareto.py --scenes glass --reps 1 --width 160 --height 120 --thresholds 0 0.3 --depths 2 3

For every scene, both renderers render the image once without antialiasing (-A) and once for each combination of
sampling method (+AM1, +AM2), threshold (+A<t>) and depth (+R<d>), always with -J (no jitter: deterministic, and
POV-Ray's jitter is random), +FP16 (16-bit PPM) and +WT<threads>. Time is the render time each program reports
(POV-Ray's Trace Time, povtrace's render_s; minimum over --reps runs), not the wall time: POV-Ray idles about 0.7 s
per process whatever the settings. Error is the RMSE against a converged ground truth over the display values
(sRGB-encoded, 0–1, all three channels), and PSNR = 20·log10(1 / RMSE).

Ground truth: povtrace renders the scene --gt-factor (16) times wider and higher without antialiasing, and each
16 x 16 block of samples is averaged in linear light (a box filter: 256 stratified samples at the sub-pixel centres
of each pixel). That is the integral over the pixel area that both AA methods approximate; it uses neither
renderer's AA code, so it does not favour povtrace's (or POV-Ray's) sample pattern, as method 2 at depth 6 would
(its samples include every sample of method 2 at lower depths). Two checks go into the summary: the same ground
truth made by POV-Ray (how far apart the renderers are before antialiasing enters) and povtrace's ground truth
at half the factor (how converged the ground truth is).

Results in --results (bench/results/pareto): pareto.csv (one row per scene, renderer and setting), pareto.md
(summary: the Pareto fronts and whether povtrace's front dominates POV-Ray's), pareto.png (gnuplot) and
pareto_run.json (header, ground-truth checks and settings, so that --resummarize can redo the summary and the plot
from the CSV without rendering).
"""
import argparse
import csv
import json
import math
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_scenes import SCENES, write_scene  # noqa: E402
from bench_tools import (REPO, cpu_name, ensure_gnuplot, gnuplot_string, load_average, now_text,  # noqa: E402
                         parse_povray_times, povray_version, read_ppm, repo_commit, run_gnuplot, run_measured, tail)

TOOLS = ("povtrace", "povray")

# ---------------------------------------------------------------------------------------------------------------
# Colour and images


def srgb_decode(v):
    return v / 12.92 if v <= 0.04045 else ((v + 0.055) / 1.055) ** 2.4


def srgb_encode(v):
    v = min(max(v, 0.0), 1.0)
    return v * 12.92 if v <= 0.0031308 else 1.055 * v ** (1 / 2.4) - 0.055


def display_values(path):
    """A PPM's samples as display values in [0, 1]; returns (width, height, list)."""
    width, height, maxval, samples = read_ppm(path)
    return width, height, [v / maxval for v in samples]


def box_filter(width, height, maxval, samples, factor):
    """Averages each factor x factor block of an sRGB-encoded image in linear light. Returns (width / factor,
    height / factor, display values of the result, share of output pixels whose block mixes clipped and unclipped
    samples in some channel: only there can the average of clipped samples differ from clipping the average)."""
    if width % factor or height % factor:
        raise ValueError(f"{width}x{height} is not a multiple of {factor}")
    lut = [srgb_decode(i / maxval) for i in range(maxval + 1)]
    out_w, out_h, row_len = width // factor, height // factor, width * 3
    out, mixed = [], 0
    scale = 1.0 / (factor * factor)
    block = factor * 3
    for oy in range(out_h):
        acc = [0.0] * row_len
        sat = [0] * row_len
        for y in range(oy * factor, (oy + 1) * factor):
            row = samples[y * row_len:(y + 1) * row_len]
            acc = list(map(float.__add__, acc, map(lut.__getitem__, row)))
            sat = list(map(int.__add__, sat, map(maxval.__eq__, row)))
        for ox in range(out_w):
            mixed_here = False
            for c in range(3):
                lo = ox * block + c
                out.append(srgb_encode(sum(acc[lo:lo + block:3]) * scale))
                n_sat = sum(sat[lo:lo + block:3])
                mixed_here |= 0 < n_sat < factor * factor
            mixed += mixed_here
    return out_w, out_h, out, mixed / (out_w * out_h)


def rmse(a, b):
    if len(a) != len(b) or not a:
        raise ValueError(f"images of {len(a)} and {len(b)} samples")
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)) / len(a))


def psnr(error):
    return math.inf if error == 0 else 20 * math.log10(1.0 / error)


# ---------------------------------------------------------------------------------------------------------------
# Pareto fronts (time and error both to be minimised)


def dominates(p, q):
    """p = (time, error) is at least as good as q in both and better in one."""
    return p[0] <= q[0] and p[1] <= q[1] and (p[0] < q[0] or p[1] < q[1])


def pareto_front(points):
    """Indices of the points no other point dominates, ordered by time. points: [(time, error), …]."""
    front = [i for i, p in enumerate(points) if not any(dominates(q, p) for q in points)]
    return sorted(front, key=lambda i: points[i])


# Between the two renderers, "as accurate" allows this relative RMSE difference (about 0.09 dB): at the same
# setting their images differ by ~1e-5 (100+ dB apart), which must not count as one being less accurate.
ERROR_TOLERANCE = 0.01


def as_accurate(p, q):
    """p's error is no worse than q's, within ERROR_TOLERANCE."""
    return p[1] <= q[1] * (1 + ERROR_TOLERANCE)


def front_coverage(ours, theirs):
    """How many points of the front `theirs` are matched or beaten in both time and error (within
    ERROR_TOLERANCE) by a point of `ours`."""
    return sum(1 for q in theirs if any(p[0] <= q[0] and as_accurate(p, q) for p in ours))


def speedup_at_equal_error(ours, theirs):
    """For each point q of `theirs`: q's time ÷ the shortest time of a point of `ours` at least as accurate
    (within ERROR_TOLERANCE); None when no point of ours is that accurate."""
    out = []
    for q in theirs:
        times = [p[0] for p in ours if as_accurate(p, q)]
        out.append(q[0] / min(times) if times and min(times) > 0 else None)
    return out


# ---------------------------------------------------------------------------------------------------------------
# Rendering


def aa_switches(setting):
    method, threshold, depth = setting
    if method == 0:
        return ["-A"]
    # POV-Ray rejects "+A0" ("Failed to parse command-line option"): the threshold always gets a decimal point.
    return [f"+AM{method}", f"+A{float(threshold)!r}", f"+R{depth}", "-J"]


def setting_label(setting):
    method, threshold, depth = setting
    return "no AA" if method == 0 else f"AM{method} A{threshold:g} R{depth}"


def render(args, tool, scene, image, width, height, switches, work):
    """One run; returns dict(ok, render_s, wall_s, error)."""
    if os.path.exists(image):
        os.remove(image)
    base = ["-D"] + switches + [f"+W{width}", f"+H{height}", "+FP16", f"+WT{args.threads}", f"+O{image}"]
    if tool == "povtrace":
        stats = image + ".stats.json"
        command = [args.povtrace] + base + [f"--stats={stats}", scene]
    else:
        command = [args.povray] + base + [scene]
    result = run_measured(command, work, args.timeout, work)
    render_s, error = None, None
    if tool == "povtrace":
        try:
            with open(stats) as f:
                render_s = json.load(f).get("render_s")
        except (OSError, ValueError) as e:
            error = f"no stats JSON ({e})"
    else:
        render_s = parse_povray_times(result["output"])["trace_s"]
    ok = result["rc"] == 0 and render_s is not None and os.path.exists(image)
    if not ok:
        error = ("timed out" if result["rc"] is None else f"exit status {result['rc']}") + ": " + \
            "; ".join(filter(None, [error, tail(result["output"])]))
    return {"ok": ok, "render_s": render_s, "wall_s": result["wall_s"], "error": error}


def ground_truth(args, tool, scene, factor, work):
    """(display values, share of clipped/unclipped blocks, render dict) of `tool`'s box-filtered ground truth."""
    image = os.path.join(work, f"gt_{tool}_{factor}.ppm")
    r = render(args, tool, scene, image, args.width * factor, args.height * factor, ["-A"], work)
    if not r["ok"]:
        return None, None, r
    width, height, maxval, samples = read_ppm(image)
    _, _, values, mixed = box_filter(width, height, maxval, samples, factor)
    os.remove(image)
    return values, mixed, r


def measure_scene(args, name, work):
    """All settings for one scene. Returns (rows, notes) where notes hold the ground-truth checks."""
    pov, _ = write_scene(name, work)
    scene = os.path.basename(pov)
    notes = {"scene": name}
    print(f"{name}: ground truth, povtrace at {args.gt_factor}x", flush=True)
    gt, mixed, r = ground_truth(args, "povtrace", scene, args.gt_factor, work)
    if gt is None:
        notes["error"] = f"povtrace ground truth failed: {r['error']}"
        return [], notes
    notes.update(gt_render_s=r["render_s"], gt_clip_mixed=mixed)
    if args.check:
        print(f"{name}: checks: POV-Ray at {args.gt_factor}x, povtrace at {args.gt_factor // 2}x", flush=True)
        pr_gt, _, r = ground_truth(args, "povray", scene, args.gt_factor, work)
        notes["povray_gt_psnr"] = psnr(rmse(pr_gt, gt)) if pr_gt else None
        notes["povray_gt_error"] = None if pr_gt else r["error"]
        half, _, r = ground_truth(args, "povtrace", scene, args.gt_factor // 2, work)
        notes["half_gt_psnr"] = psnr(rmse(half, gt)) if half else None
    settings = [(0, 0.0, 0)] + [(m, t, d) for m in args.methods for t in args.thresholds for d in args.depths]
    rows = []
    for k, setting in enumerate(settings):
        per_tool = {tool: [] for tool in TOOLS}
        images = {tool: os.path.join(work, f"{name}.{tool}.ppm") for tool in TOOLS}
        for rep in range(args.reps):
            order = TOOLS if (rep + k) % 2 == 0 else TOOLS[::-1]
            for tool in order:
                per_tool[tool].append(render(args, tool, scene, images[tool], args.width, args.height,
                                             aa_switches(setting), work))
        for tool in TOOLS:
            runs = per_tool[tool]
            ok = [r for r in runs if r["ok"]]
            row = {"scene": name, "renderer": tool, "method": setting[0], "threshold": setting[1],
                   "depth": setting[2], "setting": setting_label(setting), "switches": " ".join(aa_switches(setting)),
                   "width": args.width, "height": args.height, "reps": args.reps, "ok": f"{len(ok)}/{len(runs)}",
                   "render_s_min": min((r["render_s"] for r in ok), default=None),
                   "render_s_median": sorted(r["render_s"] for r in ok)[len(ok) // 2] if ok else None,
                   "wall_s_min": min((r["wall_s"] for r in ok), default=None),
                   "rmse": None, "psnr_db": None, "on_front": False,
                   "error": next((r["error"] for r in runs if r["error"]), "")}
            if ok and runs[-1]["ok"]:
                w, h, values = display_values(images[tool])
                if (w, h) == (args.width, args.height):
                    row["rmse"] = rmse(values, gt)
                    row["psnr_db"] = psnr(row["rmse"])
                else:
                    row["error"] = f"image is {w}x{h}"
            rows.append(row)
            print(f"  {name:10s} {setting_label(setting):16s} {tool:8s} render {fmt(row['render_s_min'])} s  "
                  f"PSNR {fmt(row['psnr_db'], 2)} dB  {row['error']}", flush=True)
    for tool in TOOLS:
        mine = [r for r in rows if r["renderer"] == tool and r["rmse"] is not None and r["render_s_min"] is not None]
        for i in pareto_front([(r["render_s_min"], r["rmse"]) for r in mine]):
            mine[i]["on_front"] = True
    return rows, notes


# ---------------------------------------------------------------------------------------------------------------
# Output


def fmt(value, digits=3):
    if value is None:
        return "–"
    if isinstance(value, float):
        if math.isinf(value):
            return "inf"
        return f"{value:.{digits}f}"
    return str(value)


def scene_summary(name, rows):
    """Front points of both renderers and the dominance verdict for one scene, as Markdown lines."""
    fronts = {tool: [r for r in rows if r["scene"] == name and r["renderer"] == tool and r["on_front"]]
              for tool in TOOLS}
    fronts = {tool: sorted(f, key=lambda r: r["render_s_min"]) for tool, f in fronts.items()}
    pts = {tool: [(r["render_s_min"], r["rmse"]) for r in f] for tool, f in fronts.items()}
    lines = []
    if not pts["povtrace"] or not pts["povray"]:
        return ["No verdict: a renderer has no measured point."], None
    covered = front_coverage(pts["povtrace"], pts["povray"])
    reverse = front_coverage(pts["povray"], pts["povtrace"])
    n_pr, n_pt = len(pts["povray"]), len(pts["povtrace"])
    if covered == n_pr and reverse < n_pt:
        verdict = "povtrace's front dominates POV-Ray's"
    elif covered == n_pr:
        verdict = "the fronts coincide"
    elif reverse == n_pt:
        verdict = "POV-Ray's front dominates povtrace's"
    else:
        verdict = "neither front dominates the other"
    lines.append(f"**{verdict}**: {covered} of POV-Ray's {n_pr} front points are matched or beaten (time and error "
                 f"both no worse, error within {100 * ERROR_TOLERANCE:g} %) by a povtrace point; {reverse} of "
                 f"povtrace's {n_pt} by a POV-Ray point.")
    speedups = [s for s in speedup_at_equal_error(pts["povtrace"], pts["povray"]) if s is not None]
    if speedups:
        lines.append(f"Speed at equal or lower error: {min(speedups):.2f}–{max(speedups):.2f} (the time of each "
                     "POV-Ray front point ÷ the time of the fastest povtrace setting at least as accurate; > 1: "
                     "povtrace is faster).")
    lines.append("")
    lines.append("| renderer | setting | render s (min) | PSNR dB | RMSE |")
    lines.append("|---|---|---:|---:|---:|")
    for tool in TOOLS:
        for r in fronts[tool]:
            lines.append(f"| {tool} | {r['setting']} | {fmt(r['render_s_min'])} | {fmt(r['psnr_db'], 2)} | "
                         f"{fmt(r['rmse'], 5)} |")
    return lines, verdict


def write_markdown_tail(f, verdicts, plot, plot_note, rows):
    """The end of a summary: the verdict per scene, the plot and the failed runs (also radiosity_pareto.py's)."""
    if verdicts:
        f.write("## Verdict\n\n" + "\n".join(f"- {name}: {v or 'no verdict'}" for name, v in verdicts) + "\n\n")
    if plot:
        f.write(f"![{plot}]({plot})\n\n")
    if plot_note:
        f.write(f"Plot: {plot_note}\n\n")
    failures = [r for r in rows if r["error"]]
    if failures:
        f.write("## Failures\n\n" + "\n".join(f"- {r['scene']} {r['renderer']} {r['setting']}: {r['error']}"
                                             for r in failures) + "\n")


def write_markdown(path, rows, notes, header, args, plot, plot_note):
    with open(path, "w") as f:
        f.write("# Antialiasing: render time against error" + (f" ({args.label})" if args.label else "") + "\n\n")
        for line in header:
            f.write(f"- {line}\n")
        f.write(f"\nError: RMSE of the display values (sRGB, 0–1) against a ground truth rendered by povtrace at "
                f"{args.gt_factor}x the width and height without AA and box-filtered in linear light "
                f"({args.gt_factor ** 2} samples a pixel); PSNR = 20·log10(1/RMSE). Time: reported render time "
                f"(POV-Ray's Trace Time, povtrace's render_s), minimum of {args.reps}. All AA settings use -J. "
                "A point is on a renderer's Pareto front when none of its other settings is both faster and more "
                "accurate.\n\n")
        verdicts = []
        for n in notes:
            name = n["scene"]
            f.write(f"## {name}\n\n")
            if n.get("error"):
                f.write(f"Not measured: {n['error']}\n\n")
                continue
            checks = [f"ground truth render {fmt(n.get('gt_render_s'))} s; {100 * n['gt_clip_mixed']:.2f} % of its "
                      "pixels average clipped and unclipped samples (there the box filter of clipped values can "
                      "differ from a renderer's clipped average)"]
            if "povray_gt_psnr" in n:
                checks.append(f"POV-Ray's ground truth against povtrace's: "
                              + (f"{fmt(n['povray_gt_psnr'], 1)} dB" if n["povray_gt_psnr"] is not None
                                 else f"failed ({n['povray_gt_error']})"))
                checks.append(f"povtrace's ground truth at {args.gt_factor // 2}x against {args.gt_factor}x: "
                              f"{fmt(n.get('half_gt_psnr'), 1)} dB (errors well below this level are not resolved)")
            f.write("Checks: " + "; ".join(checks) + ".\n\n")
            lines, verdict = scene_summary(name, rows)
            verdicts.append((name, verdict))
            f.write("\n".join(lines) + "\n\n")
        write_markdown_tail(f, verdicts, plot, plot_note, rows)


def write_plot(rows, scenes, args, work):
    """pareto.png: per scene, PSNR against render time for every setting, fronts as lines. Returns (name, note)."""
    if args.no_plots:
        return None, "not made (--no-plots)"
    gnuplot, why = ensure_gnuplot()
    if gnuplot is None:
        return None, f"not made: {why}"
    png = "pareto.png"
    stale = os.path.join(args.results, png)
    if os.path.exists(stale):
        os.remove(stale)
    panels = []
    colours = {"povtrace": "#d9622b", "povray": "#2b6cd9"}
    names = {"povtrace": "povtrace", "povray": "POV-Ray 3.7"}
    points = {0: 5, 1: 7, 2: 9}     # no AA: square, method 1: circle, method 2: triangle
    for name in scenes:
        curves = []
        for tool in TOOLS:
            mine = [r for r in rows if r["scene"] == name and r["renderer"] == tool and r["psnr_db"] is not None
                    and r["render_s_min"] and math.isfinite(r["psnr_db"])]
            if not mine:
                continue
            for method in (0, 1, 2):
                sel = [r for r in mine if r["method"] == method]
                if not sel:
                    continue
                path = os.path.join(work, f"pareto_{name}_{tool}_m{method}.dat")
                with open(path, "w") as f:
                    f.writelines(f"{r['render_s_min']:.6g} {r['psnr_db']:.6g}\n" for r in sel)
                title = f"{names[tool]}, " + ("no AA" if method == 0 else f"method {method}")
                curves.append(f"{gnuplot_string(path)} using 1:2 with points pt {points[method]} ps 1.1 "
                              f"lc rgb '{colours[tool]}' title {gnuplot_string(title)}")
            front = sorted((r for r in mine if r["on_front"]), key=lambda r: r["render_s_min"])
            path = os.path.join(work, f"pareto_{name}_{tool}_front.dat")
            with open(path, "w") as f:
                f.writelines(f"{r['render_s_min']:.6g} {r['psnr_db']:.6g}\n" for r in front)
            curves.append(f"{gnuplot_string(path)} using 1:2 with steps lw 2 lc rgb '{colours[tool]}' "
                          f"title {gnuplot_string(names[tool] + ' Pareto front')}")
        if curves:
            panels.append((name, curves))
    if not panels:
        return None, "no measured points to plot"
    subtitle = f"{args.width}x{args.height}, {args.threads} threads, min of {args.reps}, -J" + \
        (f" — {args.label}" if args.label else "")
    out = [f"set terminal pngcairo size {700 * len(panels)},560", f"set output '{png}'", "set termoption noenhanced",
           "set logscale x", "set grid", "set key bottom right font ',8'",
           "set xlabel 'render time, s (log; POV-Ray Trace Time, povtrace render_s)'",
           "set ylabel 'PSNR against ground truth, dB (higher is better)'", "set offsets graph 0.03, graph 0.03",
           f"set multiplot layout 1,{len(panels)} title "
           f"{gnuplot_string('Antialiasing: render time against error' + chr(10) + subtitle)}"]
    for name, curves in panels:
        out += [f"set title {gnuplot_string(name)}", "plot " + ", ".join(curves)]
    out.append("unset multiplot")
    script = os.path.join(work, "pareto.gp")
    with open(script, "w") as f:
        f.write("\n".join(out) + "\n")
    error = run_gnuplot(gnuplot, script, os.path.abspath(args.results))
    return (None, error) if error else (png, "")


def parse_args(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--scenes", nargs="+", default=["showcase", "glass"],
                    choices=[n for n, s in SCENES.items() if s.family not in ("parse", "legacy")])
    ap.add_argument("--width", type=int, default=240)
    ap.add_argument("--height", type=int, default=180)
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--methods", type=int, nargs="+", default=[1, 2], choices=[1, 2])
    ap.add_argument("--thresholds", type=float, nargs="+", default=[0.0, 0.05, 0.1, 0.2, 0.3, 0.5])
    ap.add_argument("--depths", type=int, nargs="+", default=[1, 2, 3, 4])
    ap.add_argument("--gt-factor", type=int, default=16, help="ground truth: this many times the width and height")
    ap.add_argument("--no-check", dest="check", action="store_false",
                    help="skip the two ground-truth checks (POV-Ray's ground truth, half the factor)")
    ap.add_argument("--povtrace", default=os.path.join(REPO, "build", "povtrace"))
    ap.add_argument("--povray", default="povray")
    ap.add_argument("--timeout", type=float, default=600, help="seconds per run")
    ap.add_argument("--results", default=os.path.join(REPO, "bench", "results", "pareto"))
    ap.add_argument("--keep", metavar="DIR", help="keep scenes and images in DIR instead of a temporary folder")
    ap.add_argument("--label", default="", help="a note for the titles, e.g. 'smoke run'")
    ap.add_argument("--no-plots", action="store_true")
    ap.add_argument("--resummarize", action="store_true",
                    help="no rendering: fronts, pareto.md and pareto.png again from pareto.csv and pareto_run.json")
    args = ap.parse_args(argv)
    args.povtrace = os.path.abspath(args.povtrace)
    if args.reps < 1:
        ap.error("--reps must be at least 1")
    if args.gt_factor < 2 or args.gt_factor % 2:
        ap.error("--gt-factor must be an even number >= 2")
    if any(not 0 <= t <= 1 for t in args.thresholds) or any(not 1 <= d <= 9 for d in args.depths):
        ap.error("thresholds are 0..1 and depths 1..9")
    return args


CSV_FIELDS = ["scene", "renderer", "method", "threshold", "depth", "setting", "switches", "width", "height", "reps",
              "ok", "render_s_min", "render_s_median", "wall_s_min", "rmse", "psnr_db", "on_front", "error"]
# What --resummarize needs besides pareto.csv: the header, the ground-truth checks and the settings of the run.
RUN_KEYS = ("scenes", "width", "height", "reps", "threads", "gt_factor", "label")


def read_csv_rows(path):
    numbers = {"method": int, "depth": int, "width": int, "height": int, "reps": int, "threshold": float,
               "render_s_min": float, "render_s_median": float, "wall_s_min": float, "rmse": float,
               "psnr_db": float}
    rows = []
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            for key, kind in numbers.items():
                row[key] = kind(row[key]) if row[key] != "" else None
            row["on_front"] = row["on_front"] == "True"
            rows.append(row)
    return rows


def write_outputs(args, rows, notes, header, work):
    """pareto.png, pareto.csv, pareto_run.json and pareto.md in args.results."""
    plot, plot_note = write_plot(rows, args.scenes, args, work)
    csv_path = os.path.join(args.results, "pareto.csv")
    with open(csv_path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=CSV_FIELDS)
        w.writeheader()
        w.writerows(rows)
    with open(os.path.join(args.results, "pareto_run.json"), "w") as f:
        json.dump({"header": header, "notes": notes, "run": {k: getattr(args, k) for k in RUN_KEYS}}, f, indent=1)
    md_path = os.path.join(args.results, "pareto.md")
    write_markdown(md_path, rows, notes, header, args, plot, plot_note)
    with open(md_path) as f:
        print(f.read())
    print(f"wrote {csv_path}, {md_path}" + (f", {os.path.join(args.results, plot)}" if plot else ""))


def resummarize(args):
    """Fronts, verdicts, Markdown and plot again from pareto.csv and pareto_run.json (no rendering)."""
    with open(os.path.join(args.results, "pareto_run.json")) as f:
        saved = json.load(f)
    for key, value in saved["run"].items():
        setattr(args, key, value)
    rows = read_csv_rows(os.path.join(args.results, "pareto.csv"))
    for row in rows:
        row["on_front"] = False
    for name in args.scenes:
        for tool in TOOLS:
            mine = [r for r in rows if r["scene"] == name and r["renderer"] == tool and r["rmse"] is not None
                    and r["render_s_min"] is not None]
            for i in pareto_front([(r["render_s_min"], r["rmse"]) for r in mine]):
                mine[i]["on_front"] = True
    with tempfile.TemporaryDirectory(prefix="povtrace-pareto-") as work:
        write_outputs(args, rows, saved["notes"], saved["header"], work)
    return 0 if rows else 1


def main(argv=None):
    args = parse_args(argv)
    if args.resummarize:
        return resummarize(args)
    work = os.path.abspath(args.keep) if args.keep else tempfile.mkdtemp(prefix="povtrace-pareto-")
    os.makedirs(work, exist_ok=True)
    os.makedirs(args.results, exist_ok=True)
    header = ([f"label: {args.label}"] if args.label else []) + [
        f"date: {now_text()}; load average at start: {load_average()}",
        f"machine: {cpu_name()}, {os.cpu_count()} logical CPUs",
        f"POV-Ray: {povray_version(args.povray)}; povtrace: {args.povtrace} (repository commit {repo_commit()})",
        f"image {args.width}x{args.height}, +WT{args.threads}, methods {args.methods}, thresholds "
        f"{[float(t) for t in args.thresholds]}, depths {args.depths}, {args.reps} repetitions each"]
    for line in header:
        print(line)
    rows, notes = [], []
    try:
        for name in args.scenes:
            scene_rows, scene_notes = measure_scene(args, name, work)
            rows += scene_rows
            notes.append(scene_notes)
        write_outputs(args, rows, notes, header, work)
    finally:
        if not args.keep:
            shutil.rmtree(work, ignore_errors=True)
    return 0 if rows else 1


if __name__ == "__main__":
    sys.exit(main())
