#pragma once
// The search work a query does (boxes and primitives tested), counted per thread so that
// the queries themselves take no counter parameter. --stats reports it (core/counters.hpp).
#include <cstdint>

namespace rt {

// Work done by queries, for --stats: the same on every machine.
struct TraversalCount {
    std::uint64_t nodes = 0;  // boxes tested
    std::uint64_t items = 0;  // primitives tested

    TraversalCount& operator+=(const TraversalCount& o) {
        nodes += o.nodes;
        items += o.items;
        return *this;
    }
};

// Every query on this thread adds its work here; the render loop takes it into each tile's
// counters (a tile runs on one thread). Queries stay free of a counter parameter, and a mesh
// inside an instance counts like any other.
inline thread_local TraversalCount traversal_tally;

// Counts in registers while a query runs, and adds them to the tally once at the end.
struct TallyScope {
    TraversalCount count;
    ~TallyScope() { traversal_tally += count; }
};

}  // namespace rt
