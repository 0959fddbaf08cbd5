#pragma once
// The MPI side of task_runner.hpp (built with HBTRACK_MPI only; <mpi.h> stays in the .cpp).
#include <memory>

#include "task_runner.hpp"

namespace hbtrack::cli {

// True when this process was started by an MPI launcher (mpirun, or srun with PMI/PMIx).
bool launched_by_mpi();

// Initialises MPI. Rank 0: a runner that hands tasks to every rank, itself included, one at a
// time as each becomes free; destroying it releases the other ranks and finalises MPI. Other
// ranks: run the tasks rank 0 sends until it releases them, finalise MPI, return nullptr.
std::unique_ptr<TaskRunner> start_mpi_task_runner();

}  // namespace hbtrack::cli
