#!/usr/bin/env python3
"""Media and photons (issue 20): povtrace against POV-Ray 3.7 on the scenes that use them, side by side in the same run.

    python3 bench/transport_bench.py                   # the media set: every case, 320x240, 3 repetitions, 2 threads
    python3 bench/transport_bench.py --set photons     # the photon set
    python3 bench/transport_bench.py --set benchmark   # POV-Ray's benchmark scene
    python3 bench/transport_bench.py --only micro mediasky --reps 1
    python3 bench/transport_bench.py --set photons --list

Cases: POV-Ray's own sample scenes that use media (or photons) and that povtrace renders (Debian's povray-examples,
from --scene-root: interior/media/*, advanced/mediasky; lights/phot_met_glass, lights/glassthing,
advanced/grenadine), and scenes of scenes/ (media ones whose POV-Ray render is deterministic and slowest; photon
ones of one light and one target, whose photon map POV-Ray shoots the same with any thread count). A sample scene
is copied into a temporary folder with its folder's files (the installed files are never written) and rendered
from there.

Both renderers run alternately with -D -A +W<w> +H<h> +FE +WT<threads> under `nice`, `--reps` times; the table
gives the fastest wall time of each (the whole process: parse, build and render), their ratio (POV-Ray time /
povtrace time: above 1, povtrace is faster) and the PSNR of povtrace's image against POV-Ray's, as povdiff computes
it. These media sample without randomness in POV-Ray (method 3 or 2 without jitter), and povtrace takes the same
samples, so equal images mean equal error: the ratio is the speed at equal error. povtrace shoots POV-Ray's photons
(its one-thread map): for sample scenes with several light × target units POV-Ray's +WT2 map is another draw, and
the PSNR is then as far as POV-Ray's own +WT2 render is from its +WT1 one (reference/photons_random/). Results go to
bench/results/media.{md,csv}, bench/results/photons.{md,csv} or bench/results/benchmark.{md,csv}.
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_tools import (REPO, cpu_name, load_average, now_text, povray_version, repo_commit,  # noqa: E402
                         run_measured, tail)

SETS = {}
SAMPLES = [
    "interior/media/media1", "interior/media/media2", "interior/media/media3", "interior/media/media4",
    "interior/media/media5", "interior/media/hollow1", "interior/media/hollow2", "interior/media/hollow3",
    "interior/media/micro", "interior/media/galaxy", "advanced/mediasky",
]
OWN = ["media_intervals10", "media_ratio", "media_atmosphere_spotlight", "media_light_area", "media_density_turbulence"]
SETS["media"] = (SAMPLES, OWN, "Media")
SETS["photons"] = (["lights/phot_met_glass", "lights/glassthing", "advanced/grenadine/grenadine"],
                   ["photons_refraction", "photons_reflection", "photons_area_light", "photons_count",
                    "photons_pass_through"], "Photons")
# POV-Ray's built-in benchmark scene (`povray --benchmark` renders the same text): photons, scattering media, fog,
# isosurfaces, julia fractals, text and a jittered area light, whose jitter makes POV-Ray's own renders differ.
SETS["benchmark"] = (["advanced/benchmark/benchmark"], [], "Benchmark")


def cases(scene_root, samples, own):
    out = []
    for rel in samples:
        path = os.path.join(scene_root, rel + ".pov")
        if os.path.exists(path):
            out.append((os.path.basename(rel), path, True))
    for name in own:
        out.append((name, os.path.join(REPO, "scenes", name + ".pov"), False))
    return out


def psnr(povdiff, a, b):
    out = subprocess.run([povdiff, a, b], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True).stdout
    for line in out.splitlines():
        if line.startswith("povdiff:"):
            for field in line.split():
                if field.startswith("psnr="):
                    return field[len("psnr="):]
    return "?"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--set", choices=sorted(SETS), default="media")
    ap.add_argument("--povtrace", default=os.path.join(REPO, "build", "povtrace"))
    ap.add_argument("--povdiff", default=None)
    ap.add_argument("--povray", default="povray")
    ap.add_argument("--scene-root", default="/usr/share/povray-3.7/scenes")
    ap.add_argument("--width", type=int, default=320)
    ap.add_argument("--height", type=int, default=240)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--timeout", type=float, default=900)
    ap.add_argument("--only", nargs="*")
    ap.add_argument("--list", action="store_true")
    ap.add_argument("--results", default=os.path.join(REPO, "bench", "results"))
    args = ap.parse_args()
    povdiff = args.povdiff or os.path.join(os.path.dirname(os.path.abspath(args.povtrace)), "povdiff")
    samples, own, title = SETS[args.set]
    all_cases = cases(args.scene_root, samples, own)
    if args.list:
        print("\n".join(name for name, _, _ in all_cases))
        return 0
    chosen = [c for c in all_cases if not args.only or c[0] in args.only]
    common = ["-D", "-A", f"+W{args.width}", f"+H{args.height}", "+FE", f"+WT{args.threads}"]
    rows = []
    with tempfile.TemporaryDirectory(prefix=f"{args.set}_bench_") as tmp:
        for name, path, sample in chosen:
            work = os.path.join(tmp, name)
            if sample:   # a copy of the scene's folder: renders write nothing next to the installed files
                shutil.copytree(os.path.dirname(path), work)
                scene = os.path.basename(path)
            else:
                os.makedirs(work)
                scene = path
            cwd = work if sample else os.path.dirname(path)
            best = {"povtrace": None, "povray": None}
            failure = ""
            for _ in range(args.reps):
                for who, program in (("povtrace", args.povtrace), ("povray", args.povray)):
                    image = os.path.join(work, f"{who}.exr")
                    r = run_measured(["nice", program] + common + [f"+O{image}", scene], cwd, args.timeout, tmp)
                    if r["rc"] != 0:
                        failure = f"{who} failed: {tail(r['output'])}"
                        break
                    if best[who] is None or r["wall_s"] < best[who]:
                        best[who] = r["wall_s"]
                if failure:
                    break
            if failure:
                rows.append({"case": name, "povtrace_s": "", "povray_s": "", "ratio": "", "psnr_db": "",
                             "note": failure})
                print(f"{name:28s} {failure}", flush=True)
                continue
            p = psnr(povdiff, os.path.join(work, "povtrace.exr"), os.path.join(work, "povray.exr"))
            ratio = best["povray"] / best["povtrace"]
            rows.append({"case": name, "povtrace_s": f"{best['povtrace']:.3f}", "povray_s": f"{best['povray']:.3f}",
                         "ratio": f"{ratio:.2f}", "psnr_db": p, "note": "sample scene" if sample else "scenes/"})
            print(f"{name:28s} povtrace {best['povtrace']:7.3f} s  povray {best['povray']:7.3f} s  "
                  f"ratio {ratio:5.2f}  PSNR {p} dB", flush=True)
    os.makedirs(args.results, exist_ok=True)
    with open(os.path.join(args.results, f"{args.set}.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=["case", "povtrace_s", "povray_s", "ratio", "psnr_db", "note"])
        w.writeheader()
        w.writerows(rows)
    with open(os.path.join(args.results, f"{args.set}.md"), "w") as f:
        f.write(f"# {title}: povtrace vs POV-Ray 3.7\n\n")
        f.write(f"{now_text()}, commit {repo_commit()}, {cpu_name()}, load average before {load_average()}; "
                f"{povray_version(args.povray)}.\n\n")
        f.write(f"{args.width}x{args.height}, -A, +WT{args.threads}, fastest of {args.reps} alternating runs, whole "
                "process. Ratio = POV-Ray time / povtrace time (above 1: povtrace faster). PSNR of povtrace's image "
                "against POV-Ray's (povdiff, linear, peak 1).\n\n")
        f.write("| case | povtrace (s) | POV-Ray (s) | ratio | PSNR (dB) | |\n|---|---:|---:|---:|---:|---|\n")
        for r in rows:
            f.write(f"| {r['case']} | {r['povtrace_s']} | {r['povray_s']} | {r['ratio']} | {r['psnr_db']} | "
                    f"{r['note']} |\n")
    print(f"wrote {os.path.join(args.results, args.set + '.md')}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
