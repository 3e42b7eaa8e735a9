// Rendering across MPI ranks (issue 18 §4.6), compiled only when CMake finds MPI (POVTRACE_HAVE_MPI).
//
// `mpirun -np N povtrace scene.pov …` with N > 1: rank 0 schedules and assembles, ranks 1…N−1 parse the scene once
// and render what they are sent. Tiles are whole 32-pixel blocks of the renderer's (0,0)-anchored grid (4 × 4
// blocks, the last ones smaller, clipped to a +SR/+ER/+SC/+EC region), handed out from a queue one at a time as
// workers report; pixels travel as raw float bytes and rank 0 writes the file through finish_job, the code a
// single process uses: the file is byte for byte the one process's (a pixel depends only on its block).
//
// A failing or dead worker is an error, never a hang: rank 0 polls (MPI_Iprobe, sleeping between polls so its
// core stays free) against a per-tile deadline of max(60 s, 10 × the slowest tile so far), or
// POVTRACE_MPI_TILE_TIMEOUT seconds when set; a worker's error message or a missed deadline is printed with the
// rank and tile, no image is written, and the job ends with MPI_Abort(…, 1). (OpenMPI's mpirun also ends the
// job itself when a rank dies.)
#pragma once

#include <atomic>

#include "app/options.hpp"

namespace povtrace::app {

// Whether this process was started by an MPI launcher with more than one rank (OMPI_COMM_WORLD_SIZE, or PMI_SIZE
// for MPICH/Slurm). Reads the environment only: a plain run never initialises MPI.
bool mpi_launched();

// The whole job on every rank: MPI_Init, the rank's part, MPI_Finalize. Returns the process's exit status.
int run_mpi_render(const RenderOptions& options, const std::atomic<bool>& interrupted);

}  // namespace povtrace::app
