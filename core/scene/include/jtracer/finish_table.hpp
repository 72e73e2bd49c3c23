#pragma once
// Equal finishes held once. The parser hands it each primitive's finish;
// one equal to a finish met before is replaced by that one, so that a file
// of a million spheres of one finish (each with its own pigment) holds the
// finish once, whether equal ones come in runs or alternate (A B A).
//
//   FinishTable finishes;
//   for (Primitive& p : scene.primitives) finishes.share(p.material.finish);

#include "jtracer/scene.hpp"

#include <cstddef>
#include <unordered_set>

namespace jt {

// Past this many distinct finishes a table stops remembering new ones (it
// still shares those it holds): a scene whose every object has a finish of
// its own gains nothing from a table as large as the scene. Once it is full,
// as many finishes in a row found in it by none stop the search: such a
// scene then pays one comparison an object, not a hash and a lookup.
inline constexpr std::size_t kMaxTabledFinishes = 4096;

// A hash of a finish's value: equal finishes (==) hash alike.
std::size_t hash_value(const Finish& finish);

class FinishTable {
  public:
    // Knows the default finish from the start: a material that sets none of
    // its properties shares the one every default Material holds.
    FinishTable() { table_.insert(last_); }

    // Makes `finish` the one held for its value when an equal one was met
    // before; otherwise remembers it for those to come.
    void share(Shared<Finish>& finish);
    // The distinct finishes remembered, the default one among them.
    std::size_t size() const { return table_.size(); }

  private:
    struct Hash {
        std::size_t operator()(const Shared<Finish>& f) const { return hash_value(*f); }
    };
    // The finish last met: a run of equal ones costs one comparison each.
    Shared<Finish> last_;
    std::size_t misses_in_a_row_ = 0;  // once full: see kMaxTabledFinishes
    std::unordered_set<Shared<Finish>, Hash> table_;
};

}  // namespace jt
