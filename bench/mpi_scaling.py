#!/usr/bin/env python3
"""MPI scaling of povtrace (issue 18): the same still (tiles) and the same animation (frames) rendered by one
process and by `mpirun -np 2` and `-np 3`, every rank with one thread (+WT1), so that N ranks use N - 1 workers
and rank 0 only schedules. Reports wall-time ratios time(1 process) / time(N ranks), the median of `--repeats`
runs each, and checks that every MPI file equals the single process's byte for byte.

    python3 bench/mpi_scaling.py [--povtrace build/povtrace] [--repeats 3] [--out bench/results/mpi_scaling.md]

On a machine with fewer cores than ranks the ratio says how much the scheduling costs, not how far it scales:
the table records the core count and the load average next to the ratios."""
import argparse
import filecmp
import os
import shutil
import statistics
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bench_tools  # noqa: E402

REPO = bench_tools.REPO
CASES = [
    # name, scene, switches
    ("still 1280x960, tiles", "scenes/showcase.pov", ["+W1280", "+H960", "+A0.3", "-J"]),
    ("animation 24 frames 320x240, frames", "tests/mpi/animation_clock.pov",
     ["+W320", "+H240", "+A0.3", "-J", "+KFI1", "+KFF24", "+KC"]),
]


def run(command, scratch):
    result = bench_tools.run_measured(command, REPO, 1800, scratch)
    if result["rc"] != 0:
        sys.exit(f"[mpi_scaling] failed ({result['rc']}): {' '.join(command)}\n{bench_tools.tail(result['output'], 12)}")
    return result["wall_s"]


def files_of(folder):
    return sorted(os.listdir(folder))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--povtrace", default=os.path.join(REPO, "build", "povtrace"))
    parser.add_argument("--mpirun", default=shutil.which("mpirun") or "mpirun")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--out", default=os.path.join(REPO, "bench", "results", "mpi_scaling.md"))
    args = parser.parse_args()
    if shutil.which(args.mpirun) is None:
        sys.exit("[mpi_scaling] no mpirun (apt-get install openmpi-bin libopenmpi-dev)")
    launcher = [args.mpirun, "--allow-run-as-root", "--oversubscribe", "--bind-to", "none"]
    rows = []
    with tempfile.TemporaryDirectory() as scratch:
        for name, scene, switches in CASES:
            times = {}
            for ranks in (1, 2, 3):
                samples = []
                for repeat in range(args.repeats):
                    out_dir = os.path.join(scratch, f"r{ranks}_{repeat}")
                    os.makedirs(out_dir)
                    command = [args.povtrace, "-D", "+WT1", *switches, scene, "+O" + os.path.join(out_dir, "img.png")]
                    if ranks > 1:
                        command = launcher + ["-np", str(ranks)] + command
                    samples.append(run(command, scratch))
                    reference = os.path.join(scratch, "r1_0")
                    for f in files_of(out_dir):
                        if not filecmp.cmp(os.path.join(reference, f), os.path.join(out_dir, f), shallow=False):
                            sys.exit(f"[mpi_scaling] {name}: {ranks} ranks wrote a different {f}")
                    if files_of(out_dir) != files_of(reference):
                        sys.exit(f"[mpi_scaling] {name}: {ranks} ranks wrote other files")
                times[ranks] = statistics.median(samples)
            rows.append((name, times))
            shutil.rmtree(scratch)
            os.makedirs(scratch)
            print(f"[mpi_scaling] {name}: " + ", ".join(f"np{n} {times[1] / times[n]:.2f}" for n in (1, 2, 3)),
                  flush=True)
    lines = [
        "# MPI scaling (bench/mpi_scaling.py)",
        "",
        f"{bench_tools.now_text()}, commit {bench_tools.repo_commit()}, {bench_tools.cpu_name()}, "
        f"{os.cpu_count()} cores, load average before: {bench_tools.load_average()}; every rank +WT1, median of "
        f"{args.repeats} runs; every MPI file byte-identical to the single process's.",
        "",
        "Ratio = wall time of one process / wall time with N ranks (N − 1 workers; rank 0 schedules and writes).",
        "",
        "| case | 1 process | mpirun -np 2 | mpirun -np 3 |",
        "|---|---|---|---|",
    ]
    for name, times in rows:
        lines.append(f"| {name} | 1.00 | {times[1] / times[2]:.2f} | {times[1] / times[3]:.2f} |")
    with open(args.out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
