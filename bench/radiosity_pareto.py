#!/usr/bin/env python3
"""Render time against error of radiosity, povtrace and POV-Ray 3.7 at the same radiosity settings.

    python3 bench/radiosity_pareto.py                        # 4 sample scenes at 160x120, 2 repetitions
    python3 bench/radiosity_pareto.py --scenes cornell --counts 20 100 --error-bounds 1 --reps 1
    python3 bench/radiosity_pareto.py --povtrace /path/to/other/build/povtrace --results /tmp/rp
    python3 bench/radiosity_pareto.py --resummarize          # summary and plot again from the CSV, no rendering

Scenes: POV-Ray's own radiosity sample scenes (from --scene-root, /usr/share/povray-3.7/scenes): cornell,
radiosity2, patio-radio_37 (its Rad_Quality 2 block) and advanced/blocks/stackerday by default; radiosity3 is
available with --scenes.

How the settings are injected (the installed files are never edited): the scene's text is copied into a temporary
folder and one line is appended after it,

    global_settings { radiosity { count N error_bound E [pretrace_end P] [nearest_count K] } }

and the copy is rendered from that folder with +L<the scene's own folder>, so its #include files (and anything else
it reads through the library path) are found as before. In POV-Ray 3.7 every global_settings block edits the same
settings and every radiosity item may repeat, the last one winning; so the appended block changes only the items it
names and keeps the scene's others (pretrace_start, recursion_limit, low_error_factor, brightness, ...). Checked:
cornell.pov with the line appended and cornell.pov with its `count 200` / `error_bound 0.5` edited to 20 / 1.8 give
the same pixels with povray +WT1 (the files differ only in the render date of the PPM header) and the same bytes
with povtrace (tests/parser/radiosity_test.cpp checks that later blocks edit the same settings).

Both renderers run with -D -A +W<w> +H<h> +FP16 +WT<threads> (2) under `nice`; povtrace in its default order
(parallel, deterministic for any thread count). --povray-order adds a third series, povtrace with
--radiosity-povray-order (one thread, POV-Ray's +WT1 order; slower by design, a check of accuracy not of speed).
No antialiasing, so that the error is the radiosity's. POV-Ray at +WT2 is not deterministic (study §6): its
error varies a little run to run; the error of a setting is that of its last repetition's image.

Time: the render time each program reports, the minimum over --reps runs. POV-Ray: `Radiosity Time` (the pretrace)
+ `Trace Time` (the final pass, which also gathers samples) from its statistics; parse and bounding are excluded.
povtrace: `render_s` of its --stats JSON (the same number as `render X s` on its last line: pretrace and final
pass).

Error: RMSE of the display values (the 16-bit PPM values scaled to 0-1, all three channels) against a converged
reference, PSNR = 20 log10(1 / RMSE). The reference is the same scene at the same size rendered by POV-Ray (+WT2)
with very high radiosity quality: the appended block sets count --ref-count (2000), error_bound --ref-error-bound
(0.15; 0.075 for patio-radio_37 and stackerday, where 0.15 was not converged enough), pretrace_end
--ref-pretrace-end (0.01; not above the scene's pretrace_start) and nearest_count --ref-nearest-count (20).
POV-Ray's reference is the neutral choice: the issue asks for povtrace to be at equal or lower error than POV-Ray
against POV-Ray's converged image. Two checks: povtrace renders the same reference too, and the RMSE between the two
references is how far apart the renderers are at convergence; and POV-Ray renders a convergence check at half the
count and 1.5 x the error_bound, whose RMSE against the reference is of the size of the reference's own error
(errors of the swept settings near either level are not resolved). All are cached in --results/references (PPM
files, not committed): POV-Ray's by scene, size and settings; povtrace's also by a hash of the povtrace binary, so
a new build makes a new one. --references-only adds references and checks to a finished run.

Output in --results (bench/results/radiosity_pareto): radiosity_pareto.csv (one row per scene, renderer and
setting), radiosity_pareto.md (per scene the Pareto fronts and, for every POV-Ray front point, the fastest povtrace
point at least as accurate and the speed ratio), radiosity_pareto.png (gnuplot) and radiosity_pareto_run.json (run
header, reference checks and settings, for --resummarize).
"""
import argparse
import csv
import hashlib
import itertools
import json
import math
import os
import re
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_tools import (REPO, cpu_name, ensure_gnuplot, gnuplot_string, load_average, now_text,  # noqa: E402
                         povray_version, repo_commit, run_gnuplot, run_measured, tail)
from pareto import (ERROR_TOLERANCE, as_accurate, display_values, fmt, front_coverage, pareto_front,  # noqa: E402
                    psnr, rmse, write_markdown_tail)

SCENE_ROOT = "/usr/share/povray-3.7/scenes"
SCENES = {
    "cornell": "radiosity/cornell.pov",
    "radiosity2": "radiosity/radiosity2.pov",
    "radiosity3": "radiosity/radiosity3.pov",
    "patio-radio_37": "radiosity/patio-radio_37.pov",
    "stackerday": "advanced/blocks/stackerday.pov",
}
DEFAULT_SCENES = ["cornell", "radiosity2", "patio-radio_37", "stackerday"]
# The reference's error_bound where the default (--ref-error-bound) is not converged enough: with 0.15, POV-Ray at
# half the count and 1.5 x the error_bound was 37.5 dB (patio-radio_37) and 31.8 dB (stackerday) from the
# reference, close to the swept settings' errors (patio 29-34 dB, stackerday 20-27 dB); cornell 53 dB, radiosity2
# 50 dB. Overridden with --ref-error-bound NAME=VALUE.
REF_ERROR_BOUND = {"patio-radio_37": 0.075, "stackerday": 0.075}
RENDERERS = ("povtrace", "povray", "povtrace-povray-order")
NAMES = {"povtrace": "povtrace", "povray": "POV-Ray 3.7", "povtrace-povray-order": "povtrace --radiosity-povray-order"}

POV_SECONDS = r":\s+\d+ hours\s+\d+ minutes\s+\d+ seconds \(([0-9.]+) seconds\)"
POV_RADIOSITY_RE = re.compile(r"Radiosity Time" + POV_SECONDS)
POV_TRACE_RE = re.compile(r"Trace Time" + POV_SECONDS)


def povray_render_times(output):
    """(pretrace s, final pass s) from POV-Ray 3.7's statistics, e.g.
    `  Radiosity Time:   0 hours  0 minutes  6 seconds (6.315 seconds)` and `  Trace Time: … (0.317 seconds)`.
    Either is None when missing (no radiosity: `Radiosity Time:   No radiosity`)."""
    found = [p.search(output) for p in (POV_RADIOSITY_RE, POV_TRACE_RE)]
    return tuple(float(m.group(1)) if m else None for m in found)


# ---------------------------------------------------------------------------------------------------------------
# Settings and scene copies


def setting_items(setting):
    """The radiosity items of a setting dict (count, error_bound, pretrace_end, nearest_count; None = the scene's)."""
    items = []
    for key in ("count", "error_bound", "pretrace_end", "nearest_count"):
        if setting.get(key) is not None:
            items.append(f"{key} {setting[key]:g}")
    return " ".join(items)


def setting_label(setting):
    short = {"count": "count", "error_bound": "eb", "pretrace_end": "pte", "nearest_count": "nc"}
    return " ".join(f"{short[k]} {setting[k]:g}" for k in short if setting.get(k) is not None)


def override_line(setting):
    return ("\n// appended by bench/radiosity_pareto.py: later radiosity items replace the scene's\n"
            f"global_settings {{ radiosity {{ {setting_items(setting)} }} }}\n")


def write_scene_copy(source, setting, work, tag):
    with open(source) as f:
        text = f.read()
    path = os.path.join(work, f"{tag}.pov")
    with open(path, "w") as f:
        f.write(text + override_line(setting))
    return path


def pretrace_start_of(source):
    """The scene's last `pretrace_start F` (a literal), or None; the reference's pretrace_end is kept below it."""
    with open(source) as f:
        found = re.findall(r"pretrace_start\s+([0-9.]+)", re.sub(r"//[^\n]*", "", f.read()))
    try:
        return float(found[-1]) if found else None
    except ValueError:
        return None


def file_hash(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()[:12]


# ---------------------------------------------------------------------------------------------------------------
# Rendering


def render(args, renderer, scene_path, library, image, work):
    """One run; returns dict(ok, render_s, pretrace_s, wall_s, error)."""
    if os.path.exists(image):
        os.remove(image)
    threads = 1 if renderer == "povtrace-povray-order" else args.threads
    base = ["-D", "-A", f"+W{args.width}", f"+H{args.height}", "+FP16", f"+WT{threads}", f"+L{library}",
            f"+O{image}"]
    stats = image + ".stats.json"
    if renderer == "povray":
        command = ["nice", args.povray] + base + [scene_path]
    else:
        extra = ["--radiosity-povray-order"] if renderer == "povtrace-povray-order" else []
        command = ["nice", args.povtrace] + base + extra + [f"--stats={stats}", scene_path]
    result = run_measured(command, work, args.timeout, work)
    render_s, pretrace_s, error = None, None, None
    if renderer == "povray":
        pretrace_s, trace_s = povray_render_times(result["output"])
        if pretrace_s is None or trace_s is None:
            error = "no `Radiosity Time` / `Trace Time` in POV-Ray's statistics"
        else:
            render_s = pretrace_s + trace_s
    else:
        try:
            with open(stats) as f:
                render_s = json.load(f).get("render_s")
        except (OSError, ValueError) as e:
            error = f"no stats JSON ({e})"
    ok = result["rc"] == 0 and render_s is not None and os.path.exists(image)
    if not ok:
        error = ("timed out" if result["rc"] is None else f"exit status {result['rc']}") + ": " + \
            "; ".join(filter(None, [error, tail(result["output"])]))
    return {"ok": ok, "render_s": render_s, "pretrace_s": pretrace_s, "wall_s": result["wall_s"], "error": error}


def reference_setting(args, name, source, check=False):
    """The reference's radiosity items; check: the convergence check's (half the count, 1.5 x the error_bound)."""
    bound = ref_error_bound(args, name)
    setting = {"count": args.ref_count / 2 if check else args.ref_count,
               "error_bound": bound * 1.5 if check else bound,
               "pretrace_end": args.ref_pretrace_end, "nearest_count": args.ref_nearest_count}
    start = pretrace_start_of(source)
    if start is not None and setting["pretrace_end"] > start:
        setting["pretrace_end"] = start
    return setting


def ref_error_bound(args, name):
    """The reference's error_bound of a scene: NAME=VALUE of --ref-error-bound, else REF_ERROR_BOUND, else the
    plain value of --ref-error-bound."""
    per_scene = dict(REF_ERROR_BOUND, **args.ref_error_bound_per_scene)
    return per_scene.get(name, args.ref_error_bound)


def reference(args, renderer, name, source, work, check=False):
    """Display values of `renderer`'s converged reference of a scene (check: the convergence check), rendered once and
    cached in --results/references. Returns (values or None, dict of render_s, settings, date, ... or error)."""
    setting = reference_setting(args, name, source, check)
    key = f"{name}_{args.width}x{args.height}_" + setting_label(setting).replace(" ", "")
    if renderer == "povray":
        key += f"_povray_wt{args.threads}"
    else:
        key += f"_povtrace-{file_hash(args.povtrace)}_wt{args.threads}"
    folder = os.path.join(args.results, "references")
    os.makedirs(folder, exist_ok=True)
    image, meta_path = os.path.join(folder, key + ".ppm"), os.path.join(folder, key + ".json")
    what = f"{renderer} reference" + (" check" if check else "")
    if os.path.exists(image) and os.path.exists(meta_path) and not args.refresh_references:
        with open(meta_path) as f:
            meta = json.load(f)
        print(f"{name}: {what} from the cache ({os.path.relpath(image, args.results)})", flush=True)
    else:
        print(f"{name}: {what} ({setting_items(setting)})", flush=True)
        path = write_scene_copy(source, setting, work, f"{name}_reference_{renderer}")
        temporary = os.path.join(work, key + ".ppm")
        r = render(args, renderer, path, os.path.dirname(source), temporary, work)
        if not r["ok"]:
            return None, {"error": r["error"]}
        shutil.move(temporary, image)
        meta = {"render_s": r["render_s"], "settings": setting_items(setting), "date": now_text(),
                "renderer": renderer, "binary": args.povtrace if renderer != "povray" else povray_version(args.povray)}
        with open(meta_path, "w") as f:
            json.dump(meta, f, indent=1)
    meta = dict(meta, file=os.path.relpath(image, args.results))
    w, h, values = display_values(image)
    if (w, h) != (args.width, args.height):
        return None, {"error": f"reference image is {w}x{h}"}
    return values, meta


def reference_notes(args, name, source, work):
    """(POV-Ray's reference values or None, notes): the reference, povtrace's reference and the check."""
    notes = {"scene": name, "source": source}
    ref, meta = reference(args, "povray", name, source, work)
    notes["reference_povray"] = meta
    if ref is None:
        notes["error"] = f"POV-Ray's reference failed: {meta['error']}"
        return None, notes
    if args.povtrace_reference:
        pt_ref, meta = reference(args, "povtrace", name, source, work)
        notes["reference_povtrace"] = meta
        if pt_ref is not None:
            notes["references_rmse"] = rmse(pt_ref, ref)
    if args.ref_check:
        check, meta = reference(args, "povray", name, source, work, check=True)
        notes["reference_check"] = meta
        if check is not None:
            notes["reference_check_rmse"] = rmse(check, ref)
    return ref, notes


def sweep(args):
    keys = ("count", "error_bound", "pretrace_end", "nearest_count")
    lists = [args.counts, args.error_bounds, args.pretrace_ends or [None], args.nearest_counts or [None]]
    return [dict(zip(keys, combo)) for combo in itertools.product(*lists)]


def measure_scene(args, name, work):
    source = os.path.join(args.scene_root, SCENES[name])
    if not os.path.exists(source):
        return [], {"scene": name, "error": f"{source} not found"}
    ref, notes = reference_notes(args, name, source, work)
    if ref is None:
        return [], notes
    renderers = ["povtrace", "povray"] + (["povtrace-povray-order"] if args.povray_order else [])
    rows = []
    for k, setting in enumerate(sweep(args)):
        path = write_scene_copy(source, setting, work, f"{name}_{k}")
        per = {r: [] for r in renderers}
        images = {r: os.path.join(work, f"{name}.{r}.ppm") for r in renderers}
        for rep in range(args.reps):
            order = renderers if (rep + k) % 2 == 0 else renderers[::-1]
            for renderer in order:
                per[renderer].append(render(args, renderer, path, os.path.dirname(source), images[renderer], work))
        for renderer in renderers:
            runs = per[renderer]
            ok = [r for r in runs if r["ok"]]
            best = min(ok, key=lambda r: r["render_s"]) if ok else None
            row = {"scene": name, "renderer": renderer, "count": setting["count"],
                   "error_bound": setting["error_bound"], "pretrace_end": setting["pretrace_end"],
                   "nearest_count": setting["nearest_count"], "setting": setting_label(setting),
                   "width": args.width, "height": args.height,
                   "threads": 1 if renderer == "povtrace-povray-order" else args.threads, "reps": args.reps,
                   "ok": f"{len(ok)}/{len(runs)}", "render_s_min": best["render_s"] if best else None,
                   "render_s_median": sorted(r["render_s"] for r in ok)[len(ok) // 2] if ok else None,
                   "pretrace_s_of_min": best["pretrace_s"] if best else None,
                   "wall_s_min": min((r["wall_s"] for r in ok), default=None),
                   "rmse": None, "psnr_db": None, "on_front": False,
                   "error": next((r["error"] for r in runs if r["error"]), "")}
            if ok and runs[-1]["ok"]:
                w, h, values = display_values(images[renderer])
                if (w, h) == (args.width, args.height):
                    row["rmse"] = rmse(values, ref)
                    row["psnr_db"] = psnr(row["rmse"])
                else:
                    row["error"] = f"image is {w}x{h}"
            rows.append(row)
            print(f"  {name:15s} {row['setting']:22s} {renderer:22s} render {fmt(row['render_s_min'])} s  "
                  f"PSNR {fmt(row['psnr_db'], 2)} dB  {row['error']}", flush=True)
    mark_fronts(rows)
    return rows, notes


def mark_fronts(rows):
    for row in rows:
        row["on_front"] = False
    for key in {(r["scene"], r["renderer"]) for r in rows}:
        mine = [r for r in rows if (r["scene"], r["renderer"]) == key and r["rmse"] is not None
                and r["render_s_min"] is not None]
        for i in pareto_front([(r["render_s_min"], r["rmse"]) for r in mine]):
            mine[i]["on_front"] = True


# ---------------------------------------------------------------------------------------------------------------
# Summary


def scene_summary(name, rows):
    """Markdown lines for one scene: verdict, the POV-Ray front matched against povtrace, both fronts."""
    def points(renderer, front_only):
        sel = [r for r in rows if r["scene"] == name and r["renderer"] == renderer and r["rmse"] is not None
               and r["render_s_min"] is not None and (r["on_front"] or not front_only)]
        return sorted(sel, key=lambda r: (r["render_s_min"], r["rmse"]))
    pr_front, pt_front, pt_all = points("povray", True), points("povtrace", True), points("povtrace", False)
    if not pr_front or not pt_front:
        return ["No verdict: a renderer has no measured point."], None
    xy = lambda sel: [(r["render_s_min"], r["rmse"]) for r in sel]  # noqa: E731
    covered = front_coverage(xy(pt_front), xy(pr_front))
    reverse = front_coverage(xy(pr_front), xy(pt_front))
    if covered == len(pr_front) and reverse < len(pt_front):
        verdict = "povtrace's front dominates POV-Ray's (povtrace ahead)"
    elif covered == len(pr_front):
        verdict = "the fronts coincide"
    elif reverse == len(pt_front):
        verdict = "POV-Ray's front dominates povtrace's (POV-Ray ahead)"
    else:
        verdict = "neither front dominates the other"
    lines = [f"**{verdict}**: {covered} of POV-Ray's {len(pr_front)} front points are matched or beaten (time and "
             f"error both no worse, error within {100 * ERROR_TOLERANCE:g} %) by a povtrace point; {reverse} of "
             f"povtrace's {len(pt_front)} by a POV-Ray point.", ""]
    lines += ["For each POV-Ray front point, the fastest povtrace setting at least as accurate (speed = POV-Ray's "
              "time ÷ povtrace's; > 1: povtrace faster):", "",
              "| POV-Ray setting | POV-Ray s | POV-Ray PSNR dB | fastest povtrace setting as accurate | povtrace s | "
              "povtrace PSNR dB | speed |", "|---|---:|---:|---|---:|---:|---:|"]
    ratios = []
    for q in pr_front:
        match = [p for p in pt_all if as_accurate((p["render_s_min"], p["rmse"]), (q["render_s_min"], q["rmse"]))]
        p = min(match, key=lambda r: r["render_s_min"]) if match else None
        if p is None:
            lines.append(f"| {q['setting']} | {fmt(q['render_s_min'])} | {fmt(q['psnr_db'], 2)} | none as accurate "
                         "| – | – | – |")
            continue
        ratio = q["render_s_min"] / p["render_s_min"] if p["render_s_min"] > 0 else None
        ratios.append(ratio)
        lines.append(f"| {q['setting']} | {fmt(q['render_s_min'])} | {fmt(q['psnr_db'], 2)} | {p['setting']} | "
                     f"{fmt(p['render_s_min'])} | {fmt(p['psnr_db'], 2)} | {fmt(ratio, 2)} |")
    ratios = [r for r in ratios if r is not None]
    if ratios:
        speed = (f"speed at equal or lower error {min(ratios):.2f}–{max(ratios):.2f} over the {len(ratios)} matched "
                 f"POV-Ray front points ({len(pr_front) - len(ratios)} unmatched)")
        lines += ["", speed[0].upper() + speed[1:] + "."]
        verdict += f"; {speed}"
    lines += ["", "Pareto fronts:", "", "| renderer | setting | render s (min) | PSNR dB | RMSE |", "|---|---|---:|---:|---:|"]
    for renderer in RENDERERS:
        for r in points(renderer, True):
            lines.append(f"| {renderer} | {r['setting']} | {fmt(r['render_s_min'])} | {fmt(r['psnr_db'], 2)} | "
                         f"{fmt(r['rmse'], 5)} |")
    return lines, verdict


def write_markdown(path, rows, notes, header, args, plot, plot_note):
    with open(path, "w") as f:
        f.write("# Radiosity: render time against error" + (f" ({args.label})" if args.label else "") + "\n\n")
        for line in header:
            f.write(f"- {line}\n")
        f.write("\nError: RMSE of the display values (16-bit PPM, 0–1) against POV-Ray's converged reference "
                f"(+WT{args.threads}, count {args.ref_count:g}, error_bound {args.ref_error_bound:g} (the scene's own in its "
                "section where it differs), pretrace_end "
                f"{args.ref_pretrace_end:g} (at most the scene's pretrace_start), nearest_count "
                f"{args.ref_nearest_count:g}); PSNR = 20·log10(1/RMSE). Time: reported render time (POV-Ray's "
                "Radiosity Time + Trace Time, povtrace's render_s), minimum of "
                f"{args.reps}. No AA. A point is on a renderer's Pareto front when none of its other settings is "
                "both faster and more accurate. The settings are appended to the scene as a second "
                "`global_settings { radiosity { … } }`; the scene's other radiosity items stay.\n\n")
        verdicts = []
        for n in notes:
            name = n["scene"]
            f.write(f"## {name}\n\n")
            if n.get("error"):
                f.write(f"Not measured: {n['error']}\n\n")
                continue
            ref = n.get("reference_povray", {})
            checks = [f"POV-Ray's reference ({ref.get('settings')}) rendered in {fmt(ref.get('render_s'))} s"]
            pt = n.get("reference_povtrace")
            if pt is None:
                checks.append("povtrace's reference not made (--no-povtrace-reference)")
            elif pt.get("error"):
                checks.append(f"povtrace's reference failed: {pt['error']}")
            else:
                checks.append(f"povtrace's reference in {fmt(pt.get('render_s'))} s; the two references differ by "
                              f"RMSE {fmt(n.get('references_rmse'), 5)} (PSNR "
                              f"{fmt(psnr(n['references_rmse']) if n.get('references_rmse') is not None else None, 2)}"
                              " dB): errors near or below this are not resolved")
            chk = n.get("reference_check")
            if chk is None:
                checks.append("no convergence check (--no-ref-check)")
            elif chk.get("error"):
                checks.append(f"the convergence check failed: {chk['error']}")
            else:
                e = n.get("reference_check_rmse")
                checks.append(f"convergence check: POV-Ray at {chk.get('settings')} ({fmt(chk.get('render_s'))} s) "
                              f"is RMSE {fmt(e, 5)} (PSNR {fmt(psnr(e) if e is not None else None, 2)} dB) from "
                              "the reference (an error of the reference's own size; the swept settings' errors "
                              "near this level are not resolved)")
            f.write("Reference: " + "; ".join(checks) + ".\n\n")
            lines, verdict = scene_summary(name, rows)
            verdicts.append((name, verdict))
            f.write("\n".join(lines) + "\n\n")
        write_markdown_tail(f, verdicts, plot, plot_note, rows)


def write_plot(rows, notes, args, work):
    """radiosity_pareto.png: per scene PSNR against render time, every setting as a point, fronts as step lines."""
    if args.no_plots:
        return None, "not made (--no-plots)"
    gnuplot, why = ensure_gnuplot()
    if gnuplot is None:
        return None, f"not made: {why}"
    png = "radiosity_pareto.png"
    stale = os.path.join(args.results, png)
    if os.path.exists(stale):
        os.remove(stale)
    colours = {"povtrace": "#d9622b", "povray": "#2b6cd9", "povtrace-povray-order": "#3a9a3a"}
    shapes = [5, 7, 9, 11, 13, 4, 6, 8]      # one point type per error_bound
    bounds = sorted({r["error_bound"] for r in rows if r["error_bound"] is not None})
    panels = []
    for n in notes:
        name = n["scene"]
        curves = []
        for renderer in RENDERERS:
            mine = [r for r in rows if r["scene"] == name and r["renderer"] == renderer and r["psnr_db"] is not None
                    and r["render_s_min"] and math.isfinite(r["psnr_db"])]
            if not mine:
                continue
            for i, eb in enumerate(bounds):
                sel = sorted((r for r in mine if r["error_bound"] == eb), key=lambda r: r["count"] or 0)
                if not sel:
                    continue
                path = os.path.join(work, f"rp_{name}_{renderer}_{i}.dat")
                with open(path, "w") as f:
                    f.writelines(f"{r['render_s_min']:.6g} {r['psnr_db']:.6g}\n" for r in sel)
                curves.append(f"{gnuplot_string(path)} using 1:2 with linespoints dt 3 lw 0.7 pt {shapes[i % 8]} "
                              f"ps 1.1 lc rgb '{colours[renderer]}' title "
                              f"{gnuplot_string(f'{NAMES[renderer]}, error_bound {eb:g}')}")
            front = sorted((r for r in mine if r["on_front"]), key=lambda r: r["render_s_min"])
            path = os.path.join(work, f"rp_{name}_{renderer}_front.dat")
            with open(path, "w") as f:
                f.writelines(f"{r['render_s_min']:.6g} {r['psnr_db']:.6g}\n" for r in front)
            curves.append(f"{gnuplot_string(path)} using 1:2 with steps lw 2 lc rgb '{colours[renderer]}' "
                          f"title {gnuplot_string(NAMES[renderer] + ' Pareto front')}")
        values = [r["psnr_db"] for r in rows if r["scene"] == name and r["psnr_db"] is not None
                  and math.isfinite(r["psnr_db"])]
        if not values:
            continue
        times = [r["render_s_min"] for r in rows if r["scene"] == name and r["render_s_min"]]
        low, high = min(values) - 1, max(values) + 2
        left, right = min(times) / 1.4, max(times) * 1.4
        top = high
        for key, colour, dash, title in (("references_rmse", "#777777", 2, "povtrace reference vs POV-Ray reference"),
                                         ("reference_check_rmse", "#222222", 4,
                                          "convergence check vs POV-Ray reference")):
            if not n.get(key):
                continue
            level = psnr(n[key])
            if level <= high + 12:     # a line far above the points would squash them: named in the key instead
                top = max(top, level + 1)
                curves.append(f"{level:.6g} with lines dt {dash} lc rgb '{colour}' title {gnuplot_string(title)}")
            else:
                curves.append(f"NaN with lines dt {dash} lc rgb '{colour}' "
                              f"title {gnuplot_string(f'{title}: {level:.1f} dB (above the plot)')}")
        if curves:
            panels.append((name, curves, low, top, left, right))
    if not panels:
        return None, "no measured points to plot"
    cols = 2 if len(panels) > 1 else 1
    layout_rows = (len(panels) + cols - 1) // cols
    subtitle = f"{args.width}x{args.height}, +WT{args.threads}, -A, min of {args.reps}; " \
               f"points along a dotted line: count {' '.join(f'{c:g}' for c in args.counts)}" + \
               (f" — {args.label}" if args.label else "")
    out = [f"set terminal pngcairo size {760 * cols},{560 * layout_rows + 40}", f"set output '{png}'",
           "set termoption noenhanced", "set logscale x", "set grid", "set key top left opaque font ',7'",
           "set xlabel 'render time, s (log; POV-Ray Radiosity + Trace Time, povtrace render_s)'",
           "set ylabel 'PSNR against POV-Ray reference, dB'", "set offsets graph 0.03, graph 0.03, 0, 0",
           f"set multiplot layout {layout_rows},{cols} title "
           f"{gnuplot_string('Radiosity: render time against error' + chr(10) + subtitle)}"]
    for name, curves, low, top, left, right in panels:
        out += [f"set title {gnuplot_string(name)}", f"set yrange [{low:.3f}:{top:.3f}]",
                f"set xrange [{left:.6g}:{right:.6g}]", "plot " + ", ".join(curves)]
    out.append("unset multiplot")
    script = os.path.join(work, "radiosity_pareto.gp")
    with open(script, "w") as f:
        f.write("\n".join(out) + "\n")
    error = run_gnuplot(gnuplot, script, os.path.abspath(args.results))
    return (None, error) if error else (png, "")


# ---------------------------------------------------------------------------------------------------------------
# Command line, files


def parse_args(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--scenes", nargs="+", default=DEFAULT_SCENES, choices=list(SCENES))
    ap.add_argument("--scene-root", default=SCENE_ROOT)
    ap.add_argument("--width", type=int, default=160)
    ap.add_argument("--height", type=int, default=120)
    ap.add_argument("--reps", type=int, default=2)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--counts", type=float, nargs="+", default=[20, 35, 50, 100, 200, 400])
    ap.add_argument("--error-bounds", type=float, nargs="+", default=[0.5, 1.0, 1.8])
    ap.add_argument("--pretrace-ends", type=float, nargs="+", help="also sweep pretrace_end (default: the scene's)")
    ap.add_argument("--nearest-counts", type=float, nargs="+", help="also sweep nearest_count (default: the scene's)")
    ap.add_argument("--ref-count", type=float, default=2000)
    ap.add_argument("--ref-error-bound", nargs="+", default=["0.15"], metavar="[NAME=]VALUE",
                    help="the reference's error_bound (0.15; patio-radio_37 and stackerday 0.075 unless NAME=VALUE)")
    ap.add_argument("--ref-pretrace-end", type=float, default=0.01)
    ap.add_argument("--ref-nearest-count", type=float, default=20)
    ap.add_argument("--no-povtrace-reference", dest="povtrace_reference", action="store_false",
                    help="skip povtrace's reference (the distance between the renderers at convergence)")
    ap.add_argument("--no-ref-check", dest="ref_check", action="store_false",
                    help="skip the convergence check (POV-Ray at half the reference count and 1.5 x its error_bound)")
    ap.add_argument("--references-only", action="store_true",
                    help="only make (or load) the references and the checks, put them into the run JSON of "
                         "--results and write the summary again from the CSV")
    ap.add_argument("--refresh-references", action="store_true", help="render the references even when cached")
    ap.add_argument("--povray-order", action="store_true",
                    help="also povtrace --radiosity-povray-order (+WT1) as a third series")
    ap.add_argument("--povtrace", default=os.path.join(REPO, "build", "povtrace"))
    ap.add_argument("--povray", default="povray")
    ap.add_argument("--timeout", type=float, default=900, help="seconds per run")
    ap.add_argument("--results", default=os.path.join(REPO, "bench", "results", "radiosity_pareto"))
    ap.add_argument("--keep", metavar="DIR", help="keep scene copies and images in DIR instead of a temporary folder")
    ap.add_argument("--label", default="", help="a note for the titles, e.g. 'smoke run'")
    ap.add_argument("--no-plots", action="store_true")
    ap.add_argument("--resummarize", action="store_true",
                    help="no rendering: fronts, .md and .png again from the CSV and the run JSON")
    args = ap.parse_args(argv)
    args.povtrace = os.path.abspath(args.povtrace)
    if args.reps < 1:
        ap.error("--reps must be at least 1")
    plain = [v for v in args.ref_error_bound if "=" not in v]
    try:
        args.ref_error_bound_per_scene = {k: float(v) for k, v in (e.split("=", 1) for e in args.ref_error_bound
                                                                     if "=" in e)}
        args.ref_error_bound = float(plain[-1]) if plain else 0.15
    except ValueError:
        ap.error("--ref-error-bound takes VALUE or NAME=VALUE numbers")
    return args


CSV_FIELDS = ["scene", "renderer", "count", "error_bound", "pretrace_end", "nearest_count", "setting", "width",
              "height", "threads", "reps", "ok", "render_s_min", "render_s_median", "pretrace_s_of_min", "wall_s_min",
              "rmse", "psnr_db", "on_front", "error"]
RUN_KEYS = ("scenes", "width", "height", "reps", "threads", "counts", "error_bounds", "pretrace_ends",
            "nearest_counts", "ref_count", "ref_error_bound", "ref_error_bound_per_scene", "ref_pretrace_end",
            "ref_nearest_count", "label",
            "povray_order")


def read_csv_rows(path):
    numbers = {"count": float, "error_bound": float, "pretrace_end": float, "nearest_count": float, "width": int,
               "height": int, "threads": int, "reps": int, "render_s_min": float, "render_s_median": float,
               "pretrace_s_of_min": float, "wall_s_min": float, "rmse": float, "psnr_db": float}
    rows = []
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            for key, kind in numbers.items():
                row[key] = kind(row[key]) if row[key] != "" else None
            row["on_front"] = row["on_front"] == "True"
            rows.append(row)
    return rows


def write_outputs(args, rows, notes, header, work):
    plot, plot_note = write_plot(rows, notes, args, work)
    csv_path = os.path.join(args.results, "radiosity_pareto.csv")
    with open(csv_path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=CSV_FIELDS)
        w.writeheader()
        w.writerows(rows)
    with open(os.path.join(args.results, "radiosity_pareto_run.json"), "w") as f:
        json.dump({"header": header, "notes": notes, "run": {k: getattr(args, k) for k in RUN_KEYS}}, f, indent=1)
    md_path = os.path.join(args.results, "radiosity_pareto.md")
    write_markdown(md_path, rows, notes, header, args, plot, plot_note)
    with open(md_path) as f:
        print(f.read())
    print(f"wrote {csv_path}, {md_path}" + (f", {os.path.join(args.results, plot)}" if plot else ""))


def resummarize(args):
    with open(os.path.join(args.results, "radiosity_pareto_run.json")) as f:
        saved = json.load(f)
    for key, value in saved["run"].items():
        setattr(args, key, value)
    rows = read_csv_rows(os.path.join(args.results, "radiosity_pareto.csv"))
    mark_fronts(rows)
    with tempfile.TemporaryDirectory(prefix="povtrace-radpareto-") as work:
        write_outputs(args, rows, saved["notes"], saved["header"], work)
    return 0 if rows else 1


def references_only(args):
    """Makes (or loads) the references and checks of --scenes and puts them into the run JSON's notes; then
    writes the summary again when the CSV exists."""
    run_json = os.path.join(args.results, "radiosity_pareto_run.json")
    saved = None
    if os.path.exists(run_json):
        with open(run_json) as f:
            saved = json.load(f)
        for key in ("width", "height", "threads", "ref_count", "ref_error_bound", "ref_error_bound_per_scene",
                    "ref_pretrace_end", "ref_nearest_count"):
            if key in saved["run"] and saved["run"][key] != getattr(args, key):
                print(f"{key} is {saved['run'][key]} in {run_json}: used instead of {getattr(args, key)}")
                setattr(args, key, saved["run"][key])
    os.makedirs(args.results, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="povtrace-radpareto-") as work:
        fresh = {}
        for name in args.scenes:
            source = os.path.join(args.scene_root, SCENES[name])
            fresh[name] = reference_notes(args, name, source, work)[1]
            print(json.dumps(fresh[name], indent=1))
    if saved is None:
        return 0
    notes = [dict(n, **fresh[n["scene"]]) if n["scene"] in fresh else n for n in saved["notes"]]
    saved["notes"] = notes
    with open(run_json, "w") as f:
        json.dump(saved, f, indent=1)
    return resummarize(args)


def main(argv=None):
    args = parse_args(argv)
    if args.resummarize:
        return resummarize(args)
    if args.references_only:
        return references_only(args)
    work = os.path.abspath(args.keep) if args.keep else tempfile.mkdtemp(prefix="povtrace-radpareto-")
    os.makedirs(work, exist_ok=True)
    os.makedirs(args.results, exist_ok=True)
    header = ([f"label: {args.label}"] if args.label else []) + [
        f"date: {now_text()}; load average at start: {load_average()}",
        f"machine: {cpu_name()}, {os.cpu_count()} logical CPUs",
        f"POV-Ray: {povray_version(args.povray)}; povtrace: {args.povtrace} (sha256 {file_hash(args.povtrace)}; "
        f"repository commit {repo_commit()})",
        f"image {args.width}x{args.height}, +WT{args.threads}, -A, counts {[f'{c:g}' for c in args.counts]}, "
        f"error_bounds {[f'{e:g}' for e in args.error_bounds]}"
        + (f", pretrace_ends {args.pretrace_ends}" if args.pretrace_ends else "")
        + (f", nearest_counts {args.nearest_counts}" if args.nearest_counts else "")
        + f", {args.reps} repetitions each"]
    for line in header:
        print(line, flush=True)
    rows, notes = [], []
    try:
        for name in args.scenes:
            scene_rows, scene_notes = measure_scene(args, name, work)
            rows += scene_rows
            notes.append(scene_notes)
        header.append(f"load average at the end: {load_average()}; finished {now_text()}")
        write_outputs(args, rows, notes, header, work)
    finally:
        if not args.keep:
            shutil.rmtree(work, ignore_errors=True)
    return 0 if rows else 1


if __name__ == "__main__":
    sys.exit(main())
