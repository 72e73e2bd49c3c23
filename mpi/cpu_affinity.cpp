#include "cpu_affinity.hpp"

#include <sched.h>
#include <unistd.h>

namespace jt::mpi {

CpuShare current_cpu_share() {
    CpuShare share;
    share.online = static_cast<int>(sysconf(_SC_NPROCESSORS_ONLN));
    cpu_set_t set;
    CPU_ZERO(&set);
    share.allowed = sched_getaffinity(0, sizeof set, &set) == 0 ? CPU_COUNT(&set) : share.online;
    return share;
}

std::optional<std::string> narrow_affinity_warning(const CpuShare& share, int rank,
                                                   const std::string& host) {
    if (share.allowed <= 0 || share.allowed >= share.online) return std::nullopt;
    return "jtracer-mpi: warning: rank " + std::to_string(rank) + " on " + host +
           " may run on only " + std::to_string(share.allowed) + " of the machine's " +
           std::to_string(share.online) +
           " CPUs (bound by mpirun, or by taskset); pass --bind-to none to mpirun to render "
           "with all of them\n";
}

}  // namespace jt::mpi
