// fairness 12.2 pass: both children built inside the call to add_inner
// The order in which C++ evaluates the two arguments is the compiler's: the nodes may be
// numbered differently, but the tree is the same, and the contract leaves the numbering free.
// @body
    if (items.size() <= builder.leaf_size() || depth >= builder.max_depth()) return builder.add_leaf(items);
    std::vector<std::uint32_t> below, above;
    for (int k = 0; k < 3; ++k) {
        const int axis = (depth + k) % 3;
        const Real split = (cell.min[axis] + cell.max[axis]) / 2;
        builder.sort(items, axis, split, below, above);
        if (2 * (below.size() + above.size()) > 3 * items.size()) continue;
        return builder.add_inner(axis, split,
                                 build_midpoint(builder, below, below_plane(cell, axis, split), depth + 1),
                                 build_midpoint(builder, above, above_plane(cell, axis, split), depth + 1));
    }
    return builder.add_leaf(items);
