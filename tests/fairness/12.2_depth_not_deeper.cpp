// fairness 12.2 fail: the children built at the same depth
// The axis never changes (depth % 3 stays), and the depth limit is never reached.
// @body
    if (items.size() <= builder.leaf_size() || depth >= builder.max_depth()) return builder.add_leaf(items);
    std::vector<std::uint32_t> below, above;
    for (int k = 0; k < 3; ++k) {
        const int axis = (depth + k) % 3;
        const Real split = (cell.min[axis] + cell.max[axis]) / 2;
        builder.sort(items, axis, split, below, above);
        if (2 * (below.size() + above.size()) > 3 * items.size()) continue;
        const BspRef left = build_midpoint(builder, below, below_plane(cell, axis, split), depth);
        const BspRef right = build_midpoint(builder, above, above_plane(cell, axis, split), depth);
        return builder.add_inner(axis, split, left, right);
    }
    return builder.add_leaf(items);
