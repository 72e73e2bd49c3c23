#pragma once
// A replaced operator new that counts what one thread allocates, for the
// idle-frame test and benchmark (an idle frame must allocate nothing). Linked
// as an object library (JTracer::counting_new): a program that links it has
// the replacement, every other program keeps the standard one.

#include <functional>

namespace jt::test {

struct Allocated {
    long long count = 0, bytes = 0;
};

// What `work` allocated with operator new on the calling thread (the render
// and loader threads are not counted: a stray wakeup is not the frame's).
// With `print_stacks`, each allocation's call stack goes to stderr.
Allocated allocated_by(const std::function<void()>& work, bool print_stacks = false);

}  // namespace jt::test
