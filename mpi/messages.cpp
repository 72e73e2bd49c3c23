#include "messages.hpp"

namespace jt::mpi {

void send_signal(int rank, int tag) {
    MPI_Send(nullptr, 0, MPI_BYTE, rank, tag, MPI_COMM_WORLD);
}

}  // namespace jt::mpi
