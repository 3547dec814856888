#include "frictionlab/campaign/mpi.hpp"

#include <cstdlib>

#ifdef FRICTIONLAB_WITH_MPI
#include <mpi.h>
#endif

namespace frictionlab {

namespace {

bool launched_by_mpi() {
    // OpenMPI's mpirun, PMIx (srun --mpi=pmix) and PMI-2 launchers each set one of these.
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
        if (std::getenv(name)) return true;
    return false;
}

bool started = false;
constexpr int report_tag = 1, case_tag = 2;

}  // namespace

#ifdef FRICTIONLAB_WITH_MPI

MpiSession::MpiSession() {
    if (!launched_by_mpi()) return;
    MPI_Init(nullptr, nullptr);
    started = true;
}

MpiSession::~MpiSession() {
    if (started) MPI_Finalize();
    started = false;
}

int mpi_rank() {
    int rank = 0;
    if (started) MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    return rank;
}

int mpi_size() {
    int size = 1;
    if (started) MPI_Comm_size(MPI_COMM_WORLD, &size);
    return size;
}

namespace mpi_work {

bool poll_report(int& worker, Report& report) {
    if (!started) return false;
    int arrived = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, report_tag, MPI_COMM_WORLD, &arrived, &status);
    if (!arrived) return false;
    int message[2];
    MPI_Recv(message, 2, MPI_INT, status.MPI_SOURCE, report_tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    worker = status.MPI_SOURCE;
    report = {message[0], message[1]};
    return true;
}

void send_case(int worker, int case_index) { MPI_Send(&case_index, 1, MPI_INT, worker, case_tag, MPI_COMM_WORLD); }

int report_and_receive(const Report& report) {
    int message[2] = {report.case_index, report.exit_status};
    MPI_Send(message, 2, MPI_INT, 0, report_tag, MPI_COMM_WORLD);
    int case_index = -1;
    MPI_Recv(&case_index, 1, MPI_INT, 0, case_tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return case_index;
}

}  // namespace mpi_work

#else

MpiSession::MpiSession() {
    (void)launched_by_mpi;
    (void)started;
    (void)report_tag;
    (void)case_tag;
}
MpiSession::~MpiSession() = default;
int mpi_rank() { return 0; }
int mpi_size() { return 1; }

namespace mpi_work {
bool poll_report(int&, Report&) { return false; }
void send_case(int, int) {}
int report_and_receive(const Report&) { return -1; }
}  // namespace mpi_work

#endif

}  // namespace frictionlab
