#include "jtracer/finish_table.hpp"

#include <bit>
#include <cstdint>
#include <functional>
#include <string>

namespace jt {
namespace {

// Mixes one more 64-bit word into a hash (the boost::hash_combine step, widened).
std::size_t mixed(std::size_t hash, std::uint64_t word) {
    return hash ^ (word + 0x9e3779b97f4a7c15ULL + (hash << 6) + (hash >> 2));
}

// 0.0 and -0.0 are equal, so they hash alike.
std::uint64_t bits(double value) {
    return value == 0.0 ? 0 : std::bit_cast<std::uint64_t>(value);
}

std::size_t mixed(std::size_t hash, const Colour& c) {
    return mixed(mixed(mixed(hash, bits(c.x)), bits(c.y)), bits(c.z));
}

}  // namespace

std::size_t hash_value(const Finish& f) {
    std::size_t h = 0;
    h = mixed(h, f.ambient);
    h = mixed(h, f.diffuse);
    h = mixed(h, f.specular);
    for (double d : {f.diffuse_k, f.specular_k, f.reflection, f.transmission, f.ior, f.checker_size,
                     f.map_size})
        h = mixed(h, bits(d));
    h = f.checker ? mixed(mixed(h, 1), *f.checker) : mixed(h, 0);
    return mixed(h, std::hash<std::string>{}(f.image_map));
}

void FinishTable::share(Shared<Finish>& finish) {
    if (finish.shares_with(last_)) return;
    if (*finish == *last_) {
        finish = last_;
        return;
    }
    const bool full = table_.size() >= kMaxTabledFinishes;
    if (full && misses_in_a_row_ >= kMaxTabledFinishes) {
        last_ = finish;
        return;
    }
    if (const auto found = table_.find(finish); found != table_.end()) {
        finish = *found;
        misses_in_a_row_ = 0;
    } else if (!full) {
        table_.insert(finish);
    } else {
        ++misses_in_a_row_;
    }
    last_ = finish;
}

}  // namespace jt
