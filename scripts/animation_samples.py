#!/usr/bin/env python3
"""Survey POV-Ray 3.7's sample animations: povtrace against POV-Ray, frame by frame.

For every sample animation .ini (scenes/animations/*/*.ini) and every portfolio .ini (scenes/portfolio/*.ini,
except the __empty.ini template) of Debian's povray-examples, the .ini's folder is copied to two scratch folders
(the portfolio scenes write HTML files with #fopen next to the scene) and, in each, the .ini is rendered with

    <renderer> NAME.ini +W160 +H120 +FE -A +GDdebug.txt [extra]

(no +O: the frames get the names the .ini implies), by povtrace in one folder and by POV-Ray in the other. Then:
  - frames:    how many frame images each wrote (files new in the folder whose extension is .exr);
  - names:     whether the sets of new file names (images, HTML pages, debug.txt …) are equal;
  - psnr:      the worst frame's PSNR by povdiff (verdict `pass` needs the regression thresholds: PSNR >= 50 dB and
               <= 0.1 % of pixels off by more than 1/255, for every frame);
  - files:     whether every new non-image file (#fopen output, the #debug file) is byte for byte equal;
  - povtrace's error line if it failed (e.g. `unsupported: <feature> is a POV-Ray feature …` with file:line:col).

Usage: python3 scripts/animation_samples.py [--povtrace build/povtrace] [--povdiff build/povdiff]
                                            [--root /usr/share/povray-3.7/scenes] [--timeout 900] [--keep DIR]
                                            [--only NAME ...] [-- extra switches]
Prints one Markdown table row per .ini.
"""
import argparse
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile

SWITCHES = ["+W160", "+H120", "+FE", "-A", "+GDdebug.txt"]


def run(cmd, cwd, timeout):
    try:
        p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=timeout, errors="replace")
        return p.returncode, p.stderr + p.stdout
    except subprocess.TimeoutExpired:
        return "timeout", ""


def first_error(text):
    for line in text.splitlines():
        if ": error: " in line or "unsupported" in line:
            return line.strip()
    lines = text.strip().splitlines()
    return lines[-1] if lines else ""


def survey(ini, args, extra):
    folder = os.path.dirname(ini)
    name = os.path.basename(ini)
    work = tempfile.mkdtemp(prefix="anim_", dir=args.keep)
    dirs = {}
    for who in ("povtrace", "povray"):
        d = os.path.join(work, who)
        shutil.copytree(folder, d)
        dirs[who] = d
    before = set(os.listdir(dirs["povray"]))
    results = {}
    for who, exe in (("povtrace", args.povtrace), ("povray", "povray")):
        status, text = run([exe, name] + SWITCHES + extra, dirs[who], args.timeout)
        new = sorted(set(os.listdir(dirs[who])) - before)
        results[who] = (status, text, new)
    pt_status, pt_text, pt_new = results["povtrace"]
    pv_status, pv_text, pv_new = results["povray"]
    row = {"ini": os.path.relpath(ini, args.root), "povtrace": pt_status, "povray": pv_status,
           "frames_pt": sum(f.endswith(".exr") for f in pt_new), "frames_pv": sum(f.endswith(".exr") for f in pv_new),
           "names": pt_new == pv_new, "only_pt": sorted(set(pt_new) - set(pv_new)),
           "only_pv": sorted(set(pv_new) - set(pt_new)), "error": "" if pt_status == 0 else first_error(pt_text)}
    worst, failing, files_equal, differing = float("inf"), [], True, []
    for f in sorted(set(pt_new) & set(pv_new)):
        a, b = os.path.join(dirs["povtrace"], f), os.path.join(dirs["povray"], f)
        if f.endswith(".exr"):
            p = subprocess.run([args.povdiff, a, b], capture_output=True, text=True)
            m = re.search(r"psnr=(\S+) .* verdict=(\S+)", p.stdout)
            psnr = float(m.group(1)) if m else float("nan")
            worst = min(worst, psnr) if psnr == psnr else worst
            if not m or m.group(2) != "pass":
                failing.append(f)
        else:
            with open(a, "rb") as fa, open(b, "rb") as fb:
                if fa.read() != fb.read():
                    files_equal = False
                    differing.append(f)
    row.update(worst=worst, failing=failing, files_equal=files_equal, differing=differing)
    if not args.keep:
        shutil.rmtree(work)
    return row


def main():
    ap = argparse.ArgumentParser()
    here = os.path.dirname(os.path.abspath(__file__))
    ap.add_argument("--povtrace", default=os.path.join(here, "..", "build", "povtrace"))
    ap.add_argument("--povdiff", default=os.path.join(here, "..", "build", "povdiff"))
    ap.add_argument("--root", default="/usr/share/povray-3.7/scenes")
    ap.add_argument("--timeout", type=float, default=900)
    ap.add_argument("--keep", help="leave the scratch folders under this folder")
    ap.add_argument("--only", nargs="*", help="only the .ini files whose name (without .ini) is listed")
    argv = sys.argv[1:]
    extra = []
    if "--" in argv:
        extra = argv[argv.index("--") + 1:]
        argv = argv[:argv.index("--")]
    args = ap.parse_args(argv)
    args.povtrace, args.povdiff = os.path.abspath(args.povtrace), os.path.abspath(args.povdiff)
    inis = sorted(glob.glob(os.path.join(args.root, "animations", "*", "*.ini")))
    inis += sorted(f for f in glob.glob(os.path.join(args.root, "portfolio", "*.ini"))
                   if os.path.basename(f) != "__empty.ini")
    if args.only:
        inis = [f for f in inis if os.path.basename(f)[:-4] in args.only]
    print("| .ini | frames povtrace / POV-Ray | file names equal | worst-frame PSNR (dB) | frames failing |"
          " other files equal | povtrace error |")
    print("|---|---|---|---|---|---|---|")
    for ini in inis:
        r = survey(ini, args, extra)
        names = "yes" if r["names"] else "no (only povtrace: %s; only POV-Ray: %s)" % (
            " ".join(r["only_pt"][:4]) or "-", " ".join(r["only_pv"][:4]) or "-")
        worst = "-" if r["worst"] == float("inf") and not r["frames_pt"] else (
            "inf" if r["worst"] == float("inf") else "%.2f" % r["worst"])
        failing = "%d (%s)" % (len(r["failing"]), " ".join(r["failing"][:3])) if r["failing"] else "0"
        files = "yes" if r["files_equal"] else "no: " + " ".join(r["differing"][:4])
        status = "" if r["povtrace"] == 0 else "exit %s: %s" % (r["povtrace"], r["error"])
        if r["povray"] != 0:
            status += " (POV-Ray exit %s)" % r["povray"]
        print("| %s | %d / %d | %s | %s | %s | %s | %s |" % (r["ini"], r["frames_pt"], r["frames_pv"], names, worst,
                                                            failing, files, status), flush=True)


if __name__ == "__main__":
    main()
