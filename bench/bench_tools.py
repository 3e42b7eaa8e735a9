"""Helpers shared by bench/run_bench.py and bench/pareto.py: running a measured process, reading POV-Ray's
statistics, installing a missing Debian package, running gnuplot, and reading 16-bit PPM images."""
import array
import datetime
import os
import platform
import re
import shutil
import signal
import subprocess
import sys
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GNU_TIME = "/usr/bin/time"

# ---------------------------------------------------------------------------------------------------------------
# Debian packages (the way scripts/setup.sh installs them: only when missing, apt-get with sudo unless root)


def package_installed(package):
    try:
        out = subprocess.run(["dpkg-query", "-W", "-f=${Status}", package], stdout=subprocess.PIPE,
                             stderr=subprocess.DEVNULL, text=True).stdout
    except OSError:
        return False
    return "ok installed" in out


def ensure_packages(packages, why):
    """Installs the missing ones of `packages` with apt-get. Returns None on success, else an error text (the
    caller carries on without the feature and says so)."""
    missing = [p for p in packages if not package_installed(p)]
    if not missing:
        return None
    if shutil.which("apt-get") is None:
        return f"{' '.join(missing)} missing and no apt-get to install it ({why})"
    sudo = [] if os.geteuid() == 0 else ["sudo"]
    print(f"[bench] installing {' '.join(missing)} ({why})", flush=True)
    env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
    for command in (sudo + ["apt-get", "update", "-qq"],
                    sudo + ["apt-get", "install", "-y", "-qq", "--no-install-recommends"] + missing):
        try:
            proc = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
        except OSError as e:
            return f"cannot run {command[0]}: {e}"
        if proc.returncode != 0:
            return f"`{' '.join(command)}` failed: {tail(proc.stdout)}"
    return None


# ---------------------------------------------------------------------------------------------------------------
# gnuplot


def ensure_gnuplot():
    """Returns (gnuplot path or None, reason when None)."""
    if shutil.which("gnuplot") is None:
        error = ensure_packages(["gnuplot-nox"], "plots")
        if error:
            return None, error
    path = shutil.which("gnuplot")
    return (path, "") if path else (None, "gnuplot not found after installing gnuplot-nox")


def run_gnuplot(gnuplot, script_path, cwd):
    """Runs one gnuplot script; returns None or an error text."""
    proc = subprocess.run([gnuplot, script_path], cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          text=True, errors="replace")
    return None if proc.returncode == 0 else f"gnuplot {os.path.basename(script_path)}: {tail(proc.stdout, 6)}"


def gnuplot_string(text):
    """A gnuplot double-quoted string literal (a newline in `text` becomes gnuplot's \\n line break)."""
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'


# ---------------------------------------------------------------------------------------------------------------
# Running one measured process

# Fallback when /usr/bin/time is missing: a fresh python process runs the command and reports its children's
# peak RSS (ru_maxrss is a maximum over all children of that process, so a fresh wrapper per run isolates it).
RUSAGE_WRAPPER = (
    "import resource, subprocess, sys\n"
    "rc = subprocess.call(sys.argv[2:])\n"
    "open(sys.argv[1], 'w').write(str(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss) + '\\n')\n"
    "sys.exit(rc)\n"
)


def run_measured(command, cwd, timeout, scratch):
    """Runs `command`; returns dict(rc, wall_s, peak_kb, output). rc is None on timeout or a missing program."""
    mem_file = os.path.join(scratch, "peak_rss.txt")
    if os.path.exists(mem_file):
        os.remove(mem_file)
    if os.access(GNU_TIME, os.X_OK):
        wrapped = [GNU_TIME, "-f", "%M", "-o", mem_file] + command
    else:
        wrapped = [sys.executable, "-c", RUSAGE_WRAPPER, mem_file] + command
    start = time.perf_counter()
    try:
        # A session of its own, so that a timeout can end the wrapper *and* the renderer it started.
        proc = subprocess.Popen(wrapped, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                text=True, errors="replace", start_new_session=True)
    except OSError as e:
        return {"rc": None, "wall_s": None, "peak_kb": None, "output": f"[bench] cannot start: {e}"}
    try:
        output, _ = proc.communicate(timeout=timeout)
        rc = proc.returncode
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        output, _ = proc.communicate()
        rc = None
        output = (output or "") + f"\n[bench] timed out after {timeout:g} s"
    wall = time.perf_counter() - start
    peak_kb = None
    try:
        with open(mem_file) as f:
            # GNU time writes "Command exited with non-zero status N" before the value when the child fails.
            lines = [line.strip() for line in f if line.strip()]
        peak_kb = int(lines[-1])
    except (OSError, ValueError, IndexError):
        pass
    return {"rc": rc, "wall_s": wall, "peak_kb": peak_kb, "output": output}


def memory_method():
    return "/usr/bin/time -f %M" if os.access(GNU_TIME, os.X_OK) else "RUSAGE_CHILDREN in a python wrapper"


POV_TIME_RE = {
    key: re.compile(label + r":\s+\d+ hours\s+\d+ minutes\s+\d+ seconds \(([0-9.]+) seconds\)")
    for key, label in (("parse_s", "Parse Time"), ("bounding_s", "Bounding Time"), ("trace_s", "Trace Time"))
}


def parse_povray_times(output):
    """POV-Ray 3.7 prints e.g. `  Trace Time:       0 hours  0 minutes  1 seconds (1.234 seconds)`."""
    times = {}
    for key, pattern in POV_TIME_RE.items():
        m = pattern.search(output)
        times[key] = float(m.group(1)) if m else None
    return times


def tail(text, lines=4):
    return " | ".join(line.strip() for line in (text or "").strip().splitlines()[-lines:])


# ---------------------------------------------------------------------------------------------------------------
# Environment description for result headers


def cpu_name():
    cpu = platform.processor() or "unknown CPU"
    try:
        with open("/proc/cpuinfo") as f:
            m = re.search(r"model name\s*:\s*(.+)", f.read())
            cpu = m.group(1).strip() if m else cpu
    except OSError:
        pass
    return cpu


def povray_version(povray):
    try:
        ver = subprocess.run([povray, "--version"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             text=True).stdout
        return next((line for line in ver.splitlines() if line.startswith("POV-Ray")), "unknown")
    except OSError:
        return "povray not found"


def repo_commit():
    try:
        commit = subprocess.run(["git", "-C", REPO, "rev-parse", "--short", "HEAD"], stdout=subprocess.PIPE,
                                stderr=subprocess.DEVNULL, text=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", REPO, "status", "--porcelain", "--untracked-files=no"],
                               stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True).stdout.strip()
        return (commit + (" with uncommitted changes" if dirty else "")) if commit else "unknown"
    except OSError:
        return "unknown"


def load_average():
    try:
        return " ".join(f"{v:.2f}" for v in os.getloadavg())
    except OSError:
        return "unknown"


def now_text():
    return datetime.datetime.now().isoformat(timespec="seconds")


# ---------------------------------------------------------------------------------------------------------------
# PPM images (binary P6, 8 or 16 bits): what both renderers write with +FP / +FP16


def read_ppm(path):
    """Returns (width, height, maxval, samples): samples is a flat array of the R, G, B integers, row by row from
    the top (an `array`, two bytes a sample for 16-bit files, so that large images stay small in memory)."""
    with open(path, "rb") as f:
        data = f.read()
    fields, pos = [], 0
    while len(fields) < 4:
        while pos < len(data) and data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            while pos < len(data) and data[pos:pos + 1] not in (b"\n", b"\r"):
                pos += 1
            continue
        start = pos
        while pos < len(data) and not data[pos:pos + 1].isspace():
            pos += 1
        fields.append(data[start:pos])
    if fields[0] != b"P6":
        raise ValueError(f"{path}: not a binary PPM (P6)")
    width, height, maxval = int(fields[1]), int(fields[2]), int(fields[3])
    pos += 1   # exactly one whitespace byte after maxval
    count = width * height * 3
    if maxval < 256:
        samples = array.array("B", data[pos:pos + count])
    else:
        samples = array.array("H", data[pos:pos + 2 * count])
        if sys.byteorder == "little":
            samples.byteswap()   # PPM stores 16-bit samples most significant byte first
    if len(samples) != count:
        raise ValueError(f"{path}: truncated ({len(samples)} of {count} samples)")
    return width, height, maxval, samples
