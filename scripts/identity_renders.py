#!/usr/bin/env python3
"""Bit-identity check for refactorings: render every reference scene and every POV-Ray sample scene that renders
with one povtrace build as 32-bit float EXR, then compare two such folders byte for byte.

A change that must not change any image (issue 17's redesign) renders with the build before and the build after:

    python3 scripts/identity_renders.py render --povtrace /tmp/before/build/povtrace --out /tmp/before-renders
    python3 scripts/identity_renders.py render --povtrace build/povtrace --out /tmp/after-renders
    python3 scripts/identity_renders.py compare /tmp/before-renders /tmp/after-renders

Reference scenes (scenes/NAME.pov with reference/NAME.exr) render as the regression tests render them (320x240,
their "// switches:" line); sample scenes (Debian's povray-examples) as scripts/sample_scenes.py does (64x48, from
the scene's own folder). A scene that povtrace refuses or fails on is recorded with its exit status and the first
line of its error, so a refusal that changes shows up too. The EXR header holds no time stamp, so equal images are
equal files.
"""
import argparse
import concurrent.futures
import glob
import hashlib
import json
import os
import shlex
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SAMPLES = "/usr/share/doc/povray/examples"


def scene_switches(scene):
    with open(scene, errors="replace") as f:
        for line in f:
            if line.startswith("// switches:"):
                return shlex.split(line[len("// switches:"):])
    return []


def jobs(scenes_dir, samples_dir):
    """(key, command, working directory) for every scene to render, run from the given copies of scenes/ and of the
    sample scenes (some scenes #write files next to themselves: never into the sources or the installed samples)."""
    out = []
    for ref in sorted(glob.glob(os.path.join(ROOT, "reference", "*.exr"))):
        name = os.path.splitext(os.path.basename(ref))[0]
        scene = os.path.join(scenes_dir, name + ".pov")
        out.append(("scenes/" + name, ["-D", "-A", "+W320", "+H240"] + scene_switches(scene) + [scene], scenes_dir))
    for scene in sorted(glob.glob(os.path.join(samples_dir, "**", "*.pov"), recursive=True)):
        rel = os.path.relpath(scene, samples_dir)
        out.append(("samples/" + rel[:-4], ["-D", "-A", "+W64", "+H48", os.path.basename(scene)],
                    os.path.dirname(scene)))
    return out


def render_one(povtrace, out_dir, timeout, job):
    key, args, cwd = job
    image = os.path.join(out_dir, key.replace("/", "__") + ".exr")
    cmd = [povtrace] + args[:-1] + ["--format=exr32", "+O" + image, args[-1]]
    try:
        p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=timeout, errors="replace")
        status = p.returncode
        first_error = next((l for l in p.stderr.splitlines() if ": error: " in l), "")
    except subprocess.TimeoutExpired:
        status, first_error = "timeout", ""
    digest = ""
    if status == 0 and os.path.exists(image):
        with open(image, "rb") as f:
            digest = hashlib.sha256(f.read()).hexdigest()
        os.remove(image)   # only the digest is kept: hundreds of EXRs add up
    return key, {"status": status, "error": first_error, "sha256": digest}


def render(a):
    os.makedirs(a.out, exist_ok=True)
    povtrace = os.path.abspath(a.povtrace)
    results = {}
    with tempfile.TemporaryDirectory() as tmp:
        scenes_dir, samples_dir = os.path.join(tmp, "scenes"), os.path.join(tmp, "samples")
        shutil.copytree(os.path.join(ROOT, "scenes"), scenes_dir)
        shutil.copytree(SAMPLES, samples_dir)
        with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
            for key, r in pool.map(lambda j: render_one(povtrace, a.out, a.timeout, j), jobs(scenes_dir, samples_dir)):
                results[key] = r
    with open(os.path.join(a.out, "renders.json"), "w") as f:
        json.dump(results, f, indent=1, sort_keys=True)
    rendered = sum(1 for r in results.values() if r["sha256"])
    print("%d scenes, %d rendered, %d refused or failed" % (len(results), rendered, len(results) - rendered))


def compare(a):
    with open(os.path.join(a.before, "renders.json")) as f:
        before = json.load(f)
    with open(os.path.join(a.after, "renders.json")) as f:
        after = json.load(f)
    differ = []
    for key in sorted(set(before) | set(after)):
        b, c = before.get(key), after.get(key)
        if b != c:
            differ.append((key, b, c))
    same = len(set(before) & set(after)) - sum(1 for k, _, _ in differ if k in before and k in after)
    rendered = sum(1 for k, r in after.items() if r["sha256"] and before.get(k) == r)
    for key, b, c in differ:
        print("DIFFERS %s\n  before %s\n  after  %s" % (key, b, c))
    print("%d scenes identical (%d of them rendered images, bit for bit), %d differ" % (same, rendered, len(differ)))
    return 1 if differ else 0


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="command", required=True)
    r = sub.add_parser("render")
    r.add_argument("--povtrace", default=os.path.join(ROOT, "build", "povtrace"))
    r.add_argument("--out", required=True)
    r.add_argument("--timeout", type=float, default=120)
    r.add_argument("--jobs", type=int, default=1, help="scenes rendered at once (each render uses every core)")
    c = sub.add_parser("compare")
    c.add_argument("before")
    c.add_argument("after")
    a = p.parse_args()
    if a.command == "render":
        render(a)
        return 0
    return compare(a)


if __name__ == "__main__":
    sys.exit(main())
