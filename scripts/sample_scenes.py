#!/usr/bin/env python3
"""Survey POV-Ray's 396 sample scenes (Debian package povray-examples): which ones povtrace renders.

Each scene is rendered at a tiny size from its own folder (as POV-Ray's own scripts do), with a time limit, and
classified: `renders`, `unsupported: <feature>` (povtrace named a POV-Ray feature it does not render yet), `error`
(any other parse or render error, with its message), `timeout` or `crash`. Prints a summary table of the most
frequent unsupported features and writes the per-scene list as CSV.

Usage: python3 scripts/sample_scenes.py [--povtrace build/povtrace] [--root /usr/share/doc/povray/examples]
                                        [--csv sample_scenes.csv] [--timeout 60]
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


def classify(povtrace, scene, timeout, outdir):
    out = os.path.join(outdir, "out.png")
    cmd = [povtrace, "-D", "-A", "+W64", "+H48", "+O" + out, os.path.basename(scene)]
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


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--povtrace", default="build/povtrace")
    ap.add_argument("--root", default="/usr/share/doc/povray/examples")
    ap.add_argument("--csv", default="sample_scenes.csv")
    ap.add_argument("--timeout", type=float, default=60)
    a = ap.parse_args()
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
            rows.append((os.path.relpath(s, a.root), status, detail))
    with open(a.csv, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["scene", "status", "detail"])
        w.writerows(rows)
    print("| status | scenes |\n|---|---:|")
    for k in ("renders", "unsupported", "error", "timeout", "crash"):
        print("| %s | %d |" % (k, counts[k]))
    print("| total | %d |\n" % len(scenes))
    print("| first unsupported feature met | scenes |\n|---|---:|")
    for feat, n in features.most_common(25):
        print("| %s | %d |" % (feat, n))
    errors = collections.Counter(d for _, s, d in rows if s == "error")
    if errors:
        print("\n| other errors | scenes |\n|---|---:|")
        for e, n in errors.most_common(15):
            print("| %s | %d |" % (e.replace("|", "\\|")[:120], n))


if __name__ == "__main__":
    main()
