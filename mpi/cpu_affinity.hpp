#pragma once
// mpirun binds each rank to one core by default when there are at most two
// ranks a machine: a rank so bound renders with one core of a many-core
// machine. Each rank checks, so that the warning names the bound one.

#include <optional>
#include <string>

namespace jt::mpi {

struct CpuShare {
    int allowed = 0;  // CPUs this process may run on (sched_getaffinity)
    int online = 0;   // CPUs the machine has online
};

CpuShare current_cpu_share();

// A warning saying what binding costs and how to lift it, when `share` is
// narrower than the machine; nothing otherwise.
std::optional<std::string> narrow_affinity_warning(const CpuShare& share, int rank,
                                                   const std::string& host);

}  // namespace jt::mpi
