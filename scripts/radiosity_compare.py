#!/usr/bin/env python3
"""Compare povtrace's radiosity renders with POV-Ray's, against POV-Ray's own thread-count spread (issue 19).

reference/radiosity/ (made by reference/make_radiosity_references.sh) holds, per case NAME of its cases.txt, POV-Ray's
+WT1 render NAME.wt1.exr (the reference) and three +WT2 renders NAME.wt2-K.exr. For each case this prints, against
NAME.wt1.exr:
  - the candidate (povtrace's render): PSNR, mean relative difference, RMS, max abs;
  - each POV-Ray +WT2 run, and the worst of them (the lowest PSNR);
  - verdict "within POV-Ray's spread" when the candidate's PSNR >= the worst +WT2 run's PSNR, else "outside".

Figures (all against the +WT1 reference, over R, G, B in linear light, as stored in the EXRs):
  - PSNR, RMS and max abs come from povdiff (build/povdiff): RMS = sqrt(mean of (b - a)^2 over every channel value),
    PSNR = 20 log10(1 / RMS) (peak 1.0, no clipping of values above 1), max abs = largest |b - a| of any channel.
    They are exactly the numbers the CTest tests radiosity_samples.NAME use.
  - mean rel = sum |b - a| / sum |a| over every channel value (the mean absolute difference relative to the mean
    reference value; robust where the reference is near black). It needs the pixel values, read with
    `oiiotool --dumpdata` (openimageio-tools); without oiiotool it is shown as n/a.

Usage:
  radiosity_compare.py [NAME...]                        POV-Ray's spread only
  radiosity_compare.py NAME --candidate IMAGE           one candidate image for one case
  radiosity_compare.py --candidate-dir DIR [NAME...]    candidates DIR/NAME.exr
  radiosity_compare.py --povtrace build/povtrace [--threads N] [--keep DIR] [NAME...]
        renders each case with povtrace exactly as POV-Ray rendered the reference (scratch copy of the scene's
        folder, from that folder: -D -A +W160 +H120 +FE [case switches] +Oout.exr scene.pov), times it (wall clock),
        and prints the time ratios POV-Ray/povtrace (POV-Ray +WT1, and the mean of POV-Ray's +WT2 runs; times.csv)
  radiosity_compare.py --write-bars reference/radiosity/bars.csv
        writes the per-case bar (worst +WT2 PSNR, with that run's mean rel and RMS) that the CTest tests read
  radiosity_compare.py --counterparts [NAME...]
        for the setting scenes (a "// counterpart: OTHER" line: the same scene without the setting): POV-Ray's
        +WT1 render of the counterpart against the case's +WT1 reference, next to the case's bar. When the
        counterpart's PSNR is below the bar, a renderer that ignored the setting would fail the test ("detects");
        otherwise the setting's effect is within POV-Ray's own thread spread and the test cannot see it.
Exit status: 0, or 1 when a candidate is outside POV-Ray's spread or a render/compare failed.
"""
import argparse
import csv
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
REF_DIR = os.path.join(REPO, "reference", "radiosity")
SAMPLES = os.environ.get("POVRAY_SAMPLES", "/usr/share/povray-3.7/scenes")
COMMON = ["-D", "-A", "+W160", "+H120", "+FE"]
WITHIN = "within POV-Ray's spread"


def read_cases(ref_dir):
    """[(name, scene path, [switches])] from cases.txt, in file order."""
    cases = []
    with open(os.path.join(ref_dir, "cases.txt")) as f:
        for line in f:
            fields = line.split()
            if not fields or fields[0].startswith("#"):
                continue
            name, scene, switches = fields[0], fields[1], fields[2:]
            if scene.startswith("samples:"):
                path = os.path.join(SAMPLES, scene[len("samples:"):])
            elif scene.startswith("repo:"):
                path = os.path.join(REPO, scene[len("repo:"):])
            else:
                sys.exit(f"cases.txt: {name}: scene {scene} is neither samples:PATH nor repo:PATH")
            cases.append((name, path, switches))
    return cases


def povdiff_figures(povdiff, reference, image):
    """rmse, psnr, max abs of image against reference, from povdiff's machine-readable last line."""
    p = subprocess.run([povdiff, reference, image, "--max-share", "1", "--min-psnr", "0"],
                       capture_output=True, text=True)
    m = re.search(r"povdiff: rmse=(\S+) psnr=(\S+) max=(\S+)", p.stdout)
    if p.returncode == 2 or not m:
        raise RuntimeError(f"povdiff {reference} {image} failed: {p.stdout}{p.stderr}")
    return float(m.group(1)), float(m.group(2)), float(m.group(3))


def pixel_values(path):
    """The R, G, B values of every pixel, row-major, via oiiotool --dumpdata."""
    p = subprocess.run(["oiiotool", "--dumpdata", path], capture_output=True, text=True, check=True)
    values = []
    for line in p.stdout.splitlines():
        if "Pixel (" in line:
            values.extend(float(v) for v in line.split(":", 1)[1].split()[:3])
    return values


class Comparer:
    def __init__(self, povdiff):
        self.povdiff = povdiff
        self.have_oiiotool = shutil.which("oiiotool") is not None
        self.cache = {}

    def values(self, path):
        if path not in self.cache:
            self.cache[path] = pixel_values(path)
        return self.cache[path]

    def figures(self, reference, image):
        rmse, psnr, max_abs = povdiff_figures(self.povdiff, reference, image)
        mean_rel = None
        if self.have_oiiotool:
            a, b = self.values(reference), self.values(image)
            if len(a) == len(b):
                total = sum(abs(x) for x in a)
                diff = sum(abs(y - x) for x, y in zip(a, b))
                mean_rel = diff / total if total > 0 else (0.0 if diff == 0 else math.inf)
        return {"psnr": psnr, "mean_rel": mean_rel, "rms": rmse, "max": max_abs}


def wt2_images(ref_dir, name):
    found = []
    k = 1
    while os.path.exists(os.path.join(ref_dir, f"{name}.wt2-{k}.exr")):
        found.append(os.path.join(ref_dir, f"{name}.wt2-{k}.exr"))
        k += 1
    return found


def read_times(ref_dir):
    """{name: {1: [wall s...], 2: [wall s...]}} from times.csv."""
    times = {}
    path = os.path.join(ref_dir, "times.csv")
    if os.path.exists(path):
        with open(path) as f:
            for row in csv.DictReader(f):
                times.setdefault(row["name"], {}).setdefault(int(row["threads"]), []).append(float(row["wall_s"]))
    return times


def render_povtrace(povtrace, scene, switches, threads, out):
    """Renders scene with povtrace from a scratch copy of its folder; returns wall seconds."""
    with tempfile.TemporaryDirectory() as tmp:
        run = os.path.join(tmp, "scene")
        shutil.copytree(os.path.dirname(scene), run)
        command = [povtrace] + COMMON + ([f"+WT{threads}"] if threads else []) + switches + \
            ["+O" + out, os.path.basename(scene)]
        start = time.monotonic()
        p = subprocess.run(command, cwd=run, capture_output=True, text=True)
        wall = time.monotonic() - start
    if p.returncode != 0 or not os.path.exists(out):
        raise RuntimeError(f"povtrace failed ({p.returncode}): {' '.join(command)}\n{(p.stdout + p.stderr)[-2000:]}")
    return wall


def counterpart_of(scene):
    with open(scene) as f:
        for line in f:
            m = re.match(r"//\s*counterpart:\s*(\S+)", line)
            if m:
                return m.group(1)
    return None


def counterparts(a, cases, comparer):
    print("| case | counterpart | counterpart vs case WT1 (PSNR, mean rel, RMS) | bar: worst WT2 vs WT1 | margin | test |")
    print("|---|---|---|---|---|---|")
    for name, scene, _ in cases:
        other = counterpart_of(scene) if scene.endswith(".pov") and os.path.exists(scene) else None
        if other is None or other == name:
            continue
        reference = os.path.join(a.ref_dir, f"{name}.wt1.exr")
        worst = min((comparer.figures(reference, r) for r in wt2_images(a.ref_dir, name)), key=lambda f: f["psnr"])
        f = comparer.figures(reference, os.path.join(a.ref_dir, f"{other}.wt1.exr"))
        margin = worst["psnr"] - f["psnr"]
        print(f"| {name} | {other} | {fmt(f)} | {worst['psnr']:.2f} dB | {margin:+.2f} dB | "
              f"{'detects' if margin > 0 else 'cannot see it'} |")
    print()
    print("margin = bar - counterpart's PSNR: how far below the bar a renderer that ignored the setting would land.")
    return 0


def fmt(f):
    if f is None:
        return "—"
    rel = "n/a" if f["mean_rel"] is None else f"{100 * f['mean_rel']:.3f} %"
    return f"{f['psnr']:.2f} dB, {rel}, {f['rms']:.5f}"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    ap.add_argument("names", nargs="*", help="cases of cases.txt (default: all)")
    ap.add_argument("--ref-dir", default=REF_DIR)
    ap.add_argument("--povdiff", default=os.path.join(REPO, "build", "povdiff"))
    ap.add_argument("--candidate", help="candidate image (exactly one NAME)")
    ap.add_argument("--candidate-dir", help="folder of candidates NAME.exr")
    ap.add_argument("--povtrace", help="render the candidates with this povtrace")
    ap.add_argument("--threads", type=int, help="with --povtrace: pass +WTn (default: povtrace's default)")
    ap.add_argument("--keep", help="with --povtrace: keep the renders in this folder as NAME.exr")
    ap.add_argument("--write-bars", help="write the per-case bars (worst +WT2 run) to this CSV")
    ap.add_argument("--counterparts", action="store_true",
                    help="does each setting scene's bar detect a renderer that ignores the setting?")
    ap.add_argument("--details", action="store_true", help="also print every +WT2 run's figures and max abs")
    a = ap.parse_args()

    if a.povtrace:
        a.povtrace = os.path.abspath(a.povtrace)  # it runs from the scene's folder
    cases = read_cases(a.ref_dir)
    known = [c[0] for c in cases]
    for n in a.names:
        if n not in known:
            sys.exit(f"unknown case {n} (cases.txt has: {' '.join(known)})")
    if a.names:
        cases = [c for c in cases if c[0] in a.names]
    if a.candidate and len(cases) != 1:
        sys.exit("--candidate needs exactly one NAME")
    if sum(bool(x) for x in (a.candidate, a.candidate_dir, a.povtrace)) > 1:
        sys.exit("use one of --candidate, --candidate-dir, --povtrace")
    if not os.access(a.povdiff, os.X_OK):
        sys.exit(f"no povdiff at {a.povdiff} (build first, or --povdiff PATH)")

    comparer = Comparer(a.povdiff)
    if a.counterparts:
        return counterparts(a, cases, comparer)
    times = read_times(a.ref_dir)
    keep = a.keep or (tempfile.mkdtemp(prefix="radiosity_compare.") if a.povtrace else None)
    if keep:
        os.makedirs(keep, exist_ok=True)
    failed = False
    rows, bars, details = [], [], []
    for name, scene, switches in cases:
        reference = os.path.join(a.ref_dir, f"{name}.wt1.exr")
        runs = wt2_images(a.ref_dir, name)
        if not os.path.exists(reference) or not runs:
            print(f"{name}: no {name}.wt1.exr or {name}.wt2-1.exr in {a.ref_dir}", file=sys.stderr)
            failed = True
            continue
        spread = [comparer.figures(reference, r) for r in runs]
        worst = min(spread, key=lambda f: f["psnr"])
        bars.append((name, worst, len(runs)))
        for r, f in zip(runs, spread):
            details.append(f"| {name} | {os.path.basename(r)} | {fmt(f)} | {f['max']:.4f} |")

        candidate, ours, wall = None, None, None
        try:
            if a.candidate:
                candidate = a.candidate
            elif a.candidate_dir:
                candidate = os.path.join(a.candidate_dir, f"{name}.exr")
            elif a.povtrace:
                candidate = os.path.join(keep, f"{name}.exr")
                if os.path.exists(candidate):
                    os.remove(candidate)
                wall = render_povtrace(a.povtrace, scene, switches, a.threads, candidate)
            if candidate:
                ours = comparer.figures(reference, candidate)
        except (RuntimeError, subprocess.CalledProcessError) as e:
            print(f"{name}: {e}", file=sys.stderr)
            failed = True
            rows.append(f"| {name} | failed | {fmt(worst)} | failed |" + (" — | — | — |" if a.povtrace else ""))
            continue
        if ours is None:
            verdict = "—"
        elif ours["psnr"] >= worst["psnr"]:
            verdict = WITHIN
        else:
            verdict = f"outside ({ours['psnr'] - worst['psnr']:+.2f} dB)"
            failed = True
        row = f"| {name} | {fmt(ours)} | {fmt(worst)} | {verdict} |"
        if a.povtrace:
            t = times.get(name, {})
            t1 = t.get(1, [None])[0]
            t2 = sum(t[2]) / len(t[2]) if t.get(2) else None
            ratio = lambda pov: "n/a" if pov is None else f"{pov / wall:.2f}"
            row += f" {wall:.2f} s | {ratio(t1)} | {ratio(t2)} |"
        rows.append(row)

    if a.write_bars:
        with open(a.write_bars, "w", newline="") as f:
            f.write("# Per case: the worst (lowest-PSNR) of POV-Ray's +WT2 renders against its +WT1 render, from\n"
                    "# scripts/radiosity_compare.py --write-bars (povdiff's PSNR and RMS, linear RGB, peak 1.0;\n"
                    "# mean_rel = sum|b-a| / sum|a|). tests/regression reads name and worst_wt2_psnr_db (povdiff's\n"
                    "# 3-decimal PSNR minus 0.0005 dB, the lowest the unrounded value can be).\n")
            w = csv.writer(f, lineterminator="\n")
            w.writerow(["name", "worst_wt2_psnr_db", "mean_rel", "rms", "max_abs", "wt2_runs"])
            for name, worst, n in bars:
                rel = "" if worst["mean_rel"] is None else f"{worst['mean_rel']:.6f}"
                # povdiff prints PSNR rounded to 0.001 dB: the bar is that figure minus half a unit, the lowest value
                # the unrounded PSNR can have, so the worst +WT2 run itself meets its bar in povdiff's test.
                w.writerow([name, f"{worst['psnr'] - 0.0005:.4f}", rel, f"{worst['rms']:.6f}", f"{worst['max']:.5f}", n])

    head = "| scene | povtrace vs WT1 (PSNR, mean rel, RMS) | POV-Ray WT2 vs WT1, worst of runs (PSNR, mean rel, RMS) | verdict |"
    rule = "|---|---|---|---|"
    if a.povtrace:
        head += " povtrace time | POV-Ray WT1 / povtrace | POV-Ray WT2 (mean) / povtrace |"
        rule += "---|---|---|"
    print(head)
    print(rule)
    for r in rows:
        print(r)
    print()
    print(f'verdict "{WITHIN}": povtrace\'s PSNR against the +WT1 reference is >= the lowest PSNR of POV-Ray\'s '
          "+WT2 renders against the same reference (povdiff's PSNR: linear RGB as stored, peak 1.0).")
    if a.details:
        print()
        print("| scene | POV-Ray run | vs WT1 (PSNR, mean rel, RMS) | max abs |")
        print("|---|---|---|---|")
        for d in details:
            print(d)
    if a.povtrace and not a.keep:
        print(f"\npovtrace renders: {keep}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
