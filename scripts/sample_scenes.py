#!/usr/bin/env python3
"""Survey POV-Ray's 396 sample scenes (Debian package povray-examples): which ones povtrace renders.

Each scene is rendered at a tiny size from its own folder (as POV-Ray's own scripts do), with a time limit, and
classified: `renders`, `unsupported: <feature>` (povtrace named a POV-Ray feature it does not render yet), `error`
(any other parse or render error, with its message), `timeout` or `crash`. Prints a summary table of the most
frequent unsupported features and writes the per-scene list as CSV.

Usage: python3 scripts/sample_scenes.py [--povtrace build/povtrace] [--root /usr/share/doc/povray/examples]
                                        [--csv sample_scenes.csv] [--timeout 60] [--compare]

With --compare, every scene povtrace renders is rendered by POV-Ray too (same switches, same size) and the two
images are compared with povdiff (next to povtrace): the CSV gains psnr, share of pixels over 1/255 and verdict
columns, and a table of the scenes furthest from POV-Ray is printed (the image thresholds are the regression
tests': PSNR >= 50 dB, <= 0.1 % of pixels off).
"""
import argparse
import collections
import csv
import os
import re
import shutil
import subprocess
import sys
import tempfile


SIZE = ["+W64", "+H48"]


def classify(povtrace, scene, timeout, outdir):
    out = os.path.join(outdir, "out.png")
    cmd = [povtrace, "-D", "-A"] + SIZE + ["+O" + out, os.path.basename(scene)]
    try:
        p = subprocess.run(cmd, cwd=os.path.dirname(scene), capture_output=True, text=True,
                           timeout=timeout, errors="replace")
    except subprocess.TimeoutExpired:
        return "timeout", ""
    if p.returncode == 0:
        return "renders", ""
    if p.returncode < 0:
        return "crash", "signal %d" % -p.returncode
    first = next((l for l in p.stderr.splitlines() if ": error: " in l), p.stderr.strip().splitlines()[:1] or [""])
    first = first if isinstance(first, str) else first[0]
    m = re.search(r"unsupported: (.*?) is a POV-Ray feature", first)
    if m:
        return "unsupported", m.group(1)
    return "error", first.split(": error: ", 1)[-1]


def compare_with_povray(povdiff, scene, timeout, outdir):
    """POV-Ray's render of the scene against povtrace's out.png: (psnr, share, verdict) or an error text."""
    ours, theirs = os.path.join(outdir, "out.png"), os.path.join(outdir, "povray.png")
    if os.path.exists(theirs):
        os.remove(theirs)
    cmd = ["povray", "-D", "-A"] + SIZE + ["+O" + theirs, os.path.basename(scene)]
    try:
        subprocess.run(cmd, cwd=os.path.dirname(scene), capture_output=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return ("", "", "povray timeout")
    if not os.path.exists(theirs):
        return ("", "", "povray failed")
    p = subprocess.run([povdiff, ours, theirs], capture_output=True, text=True)
    m = re.search(r"psnr=(\S+) .*share=(\S+) verdict=(\S+)", p.stdout)
    return (m.group(1), m.group(2), m.group(3)) if m else ("", "", "povdiff failed")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--povtrace", default="build/povtrace")
    ap.add_argument("--root", default="/usr/share/doc/povray/examples")
    ap.add_argument("--csv", default="sample_scenes.csv")
    ap.add_argument("--timeout", type=float, default=60)
    ap.add_argument("--compare", action="store_true", help="also render with POV-Ray and compare the images")
    a = ap.parse_args()
    povdiff = os.path.join(os.path.dirname(os.path.abspath(a.povtrace)), "povdiff")
    povtrace = os.path.abspath(a.povtrace)
    scenes = sorted(os.path.join(d, f) for d, _, fs in os.walk(a.root) for f in fs if f.endswith(".pov"))
    if not scenes:
        sys.exit("no scenes under %s (apt-get install povray-examples)" % a.root)
    rows, counts, features = [], collections.Counter(), collections.Counter()
    with tempfile.TemporaryDirectory() as tmp:
        # Scenes run in a private copy of the examples: some #write files next to themselves.
        copy = os.path.join(tmp, "examples")
        shutil.copytree(a.root, copy)
        for s in scenes:
            status, detail = classify(povtrace, os.path.join(copy, os.path.relpath(s, a.root)), a.timeout, tmp)
            counts[status] += 1
            if status == "unsupported":
                features[detail] += 1
            row = (os.path.relpath(s, a.root), status, detail)
            if a.compare:
                scene = os.path.join(copy, os.path.relpath(s, a.root))
                row += compare_with_povray(povdiff, scene, a.timeout, tmp) if status == "renders" else ("", "", "")
            rows.append(row)
    with open(a.csv, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["scene", "status", "detail"] + (["psnr", "share", "verdict"] if a.compare else []))
        w.writerows(rows)
    print("| status | scenes |\n|---|---:|")
    for k in ("renders", "unsupported", "error", "timeout", "crash"):
        print("| %s | %d |" % (k, counts[k]))
    print("| total | %d |\n" % len(scenes))
    print("| first unsupported feature met | scenes |\n|---|---:|")
    for feat, n in features.most_common(25):
        print("| %s | %d |" % (feat, n))
    errors = collections.Counter(r[2] for r in rows if r[1] == "error")
    if errors:
        print("\n| other errors | scenes |\n|---|---:|")
        for e, n in errors.most_common(15):
            print("| %s | %d |" % (e.replace("|", "\\|")[:120], n))
    if a.compare:
        compared = [r for r in rows if r[1] == "renders"]
        verdicts = collections.Counter(r[5] for r in compared)
        print("\n| against POV-Ray (%s) | scenes |\n|---|---:|" % " ".join(SIZE))
        for v in ("pass", "fail", "povray failed", "povray timeout", "povdiff failed"):
            print("| %s | %d |" % (v, verdicts[v]))
        def psnr(r):
            return float(r[3]) if r[3] not in ("", "inf") else (1e9 if r[3] == "inf" else -1)
        worst = sorted((r for r in compared if r[5] == "fail"), key=psnr)
        if worst:
            print("\n| furthest from POV-Ray | PSNR (dB) | pixels off |\n|---|---:|---:|")
            for r in worst[:40]:
                print("| %s | %s | %.2f %% |" % (r[0], r[3], 100 * float(r[4] or 0)))


if __name__ == "__main__":
    main()
