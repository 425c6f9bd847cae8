// fairness 12.2 pass: the cut at min + (max - min)/2, half the cell's width past its lower face
// The cell's middle, rounded in another order than (min + max)/2: the two can differ in the last
// place (issue 42), which the contract allows.
// @body
    if (items.size() <= builder.leaf_size() || depth >= builder.max_depth()) return builder.add_leaf(items);
    std::vector<std::uint32_t> below, above;
    for (int k = 0; k < 3; ++k) {
        const int axis = (depth + k) % 3;
        const Real split = cell.min[axis] + (cell.max[axis] - cell.min[axis]) / 2;
        builder.sort(items, axis, split, below, above);
        if (2 * (below.size() + above.size()) > 3 * items.size()) continue;
        const BspRef left = build_midpoint(builder, below, below_plane(cell, axis, split), depth + 1);
        const BspRef right = build_midpoint(builder, above, above_plane(cell, axis, split), depth + 1);
        return builder.add_inner(axis, split, left, right);
    }
    return builder.add_leaf(items);
