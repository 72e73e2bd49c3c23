#include "messages.hpp"

#include <cstdio>
#include <cstdlib>

namespace jt::mpi {

void send_signal(int rank, int tag) {
    MPI_Send(nullptr, 0, MPI_BYTE, rank, tag, MPI_COMM_WORLD);
}

void abort_on_malformed_message(int rank) {
    std::fprintf(stderr, "jtracer-mpi: rank %d sent a malformed message; nothing was written\n",
                 rank);
    MPI_Abort(MPI_COMM_WORLD, 3);
    std::abort();  // MPI_Abort does not return
}

}  // namespace jt::mpi
