#!/usr/bin/env python3
"""What each specialised path gains (issue 6 item 3), and proof that it changes no pixel.

For each scene and each specialisation povtrace offers (`--no-specialise=NAME`), the scene is rendered alternately
with every path on and with that one path off (the general path), `--reps` times each, on one thread so that the
two runs compete for nothing. The table gives the minimum render time of each, their ratio (the gain: general ÷
specialised, > 1 when the specialisation pays) and whether the two images are the same file, bit for bit (32-bit
float EXR). A specialisation the scene does not use shows a gain of about 1 (noise) and identical images.

Scenes: the bench's (bench_scenes.py) plus `grid_10000_no_shadow`, the 10,000-sphere grid with every object
`no_shadow`, which is what `no-shadow-rays` is for.

Usage: python3 bench/specialisation_gain.py [--povtrace build/povtrace] [--reps 5] [--width 640 --height 480]
                                            [--only NAME ...] [--results bench/results]
Writes RESULTS/specialisation_gain.md and .csv.
"""
import argparse
import csv
import datetime
import filecmp
import json
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import bench_scenes  # noqa: E402

SPECIALISATIONS = ["nearest-shadow-first", "no-shadow-rays", "embree-meshes"]
DEFAULT_SCENES = ["showcase", "grid_10000", "grid_10000_no_shadow", "glass", "mesh_10000", "mesh2_10000",
                  "mesh_99856"]


def no_shadow_text(text):
    """Every object of the scene text made no_shadow (the objects are one per line, each closed by its last }). """
    return re.sub(r"^((?:sphere|plane) \{.*)\}$", r"\1 no_shadow }", text, flags=re.M)


def write_scene(name, folder):
    if name == "grid_10000_no_shadow":
        path = os.path.join(folder, name + ".pov")
        with open(path, "w") as f:
            f.write(no_shadow_text(bench_scenes.grid_scene_text(10000)))
        return path
    return bench_scenes.write_scene(name, folder)[0]


def render(args, scene, image, extra):
    stats = image + ".json"
    cmd = [args.povtrace, os.path.basename(scene), f"+W{args.width}", f"+H{args.height}", "-A", "+WT1",
           "--format=exr32", "+O" + image, "--stats=" + stats] + extra
    p = subprocess.run(cmd, cwd=os.path.dirname(scene), capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed: {p.stderr.strip()}")
    with open(stats) as f:
        return json.load(f)["render_s"]


def measure(args, scene, name, work):
    rows = []
    for spec in SPECIALISATIONS:
        best = {"on": float("inf"), "off": float("inf")}
        images = {k: os.path.join(work, f"{name}.{k}.exr") for k in best}
        for _ in range(args.reps):
            best["on"] = min(best["on"], render(args, scene, images["on"], []))
            best["off"] = min(best["off"], render(args, scene, images["off"], ["--no-specialise=" + spec]))
        same = filecmp.cmp(images["on"], images["off"], shallow=False)
        rows.append({"scene": name, "specialisation": spec, "specialised_s": best["on"], "general_s": best["off"],
                     "gain": best["off"] / best["on"], "identical": "yes" if same else "NO"})
        print(f"{name:24} {spec:22} {best['on']:.4f} s  general {best['off']:.4f} s  gain {rows[-1]['gain']:.3f}"
              f"  identical {rows[-1]['identical']}", flush=True)
    return rows


def write_results(args, rows):
    os.makedirs(args.results, exist_ok=True)
    with open(os.path.join(args.results, "specialisation_gain.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    load = " ".join(f"{x:.2f}" for x in os.getloadavg())
    lines = [
        "# What each specialised path gains",
        "",
        f"- date: {datetime.datetime.now().isoformat(timespec='seconds')}; load average at the end: {load}",
        f"- {args.width}x{args.height}, -A, 1 thread, {args.reps} alternated repetitions each; times are the minimum "
        "render_s; gain = general ÷ specialised (> 1: the specialisation pays); identical = the two 32-bit EXR "
        "files are the same bytes",
        "",
        "| scene | specialisation | specialised s | general s | gain | identical |",
        "|---|---|---:|---:|---:|---|",
    ]
    for r in rows:
        lines.append(f"| {r['scene']} | {r['specialisation']} | {r['specialised_s']:.4f} | {r['general_s']:.4f} | "
                     f"{r['gain']:.3f} | {r['identical']} |")
    with open(os.path.join(args.results, "specialisation_gain.md"), "w") as f:
        f.write("\n".join(lines) + "\n")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--povtrace", default=os.path.join(REPO, "build", "povtrace"))
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--width", type=int, default=640)
    ap.add_argument("--height", type=int, default=480)
    ap.add_argument("--only", nargs="+", default=DEFAULT_SCENES)
    ap.add_argument("--results", default=os.path.join(HERE, "results"))
    args = ap.parse_args(argv)
    args.povtrace = os.path.abspath(args.povtrace)
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for name in args.only:
            rows += measure(args, write_scene(name, work), name, work)
    write_results(args, rows)
    print("wrote", os.path.join(args.results, "specialisation_gain.md"))
    return 0 if all(r["identical"] == "yes" for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
