#pragma once
// MPI for campaigns, when FrictionLab is built with it (FRICTIONLAB_WITH_MPI): started only when the
// process was launched by mpirun or srun, so that a plain `frictionlab sweep` never needs MPI.
namespace frictionlab {

/// Initialises MPI for the lifetime of the object if this process was launched by an MPI launcher.
class MpiSession {
public:
    MpiSession();
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;
};

/// This process's rank and the number of ranks: 0 and 1 without MPI.
int mpi_rank();
int mpi_size();

}  // namespace frictionlab

namespace frictionlab::mpi_work {

/// What a worker rank tells rank 0: the case it finished (-1: none yet) and how its process ended.
struct Report {
    int case_index = -1;
    int exit_status = 0;  // raw waitpid status
};

/// Rank 0: a report from any worker if one has arrived (never blocks).
bool poll_report(int& worker, Report& report);
/// Rank 0: the next case for a worker, or -1 to stop it.
void send_case(int worker, int case_index);
/// A worker: reports and waits for its next case (-1: stop).
int report_and_receive(const Report& report);

}  // namespace frictionlab::mpi_work
