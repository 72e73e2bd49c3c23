#include "messages.hpp"

#include <chrono>
#include <thread>

namespace jt::mpi {

double wait_for_message(int source, int tag, MPI_Status& status) {
    const auto start = std::chrono::steady_clock::now();
    int arrived = 0;
    MPI_Iprobe(source, tag, MPI_COMM_WORLD, &arrived, &status);
    while (!arrived) {
        std::this_thread::sleep_for(std::chrono::microseconds(100));
        MPI_Iprobe(source, tag, MPI_COMM_WORLD, &arrived, &status);
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace jt::mpi
