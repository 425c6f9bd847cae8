// fairness 12.2 fail: the cut at the middle of the items' boxes, not of the cell
// That is the midpoint BVH's rule (§10.3), not this tree's: the contract and §12.4 cut the
// cell, so that every cell is half its parent.
// @body
    if (items.size() <= builder.leaf_size() || depth >= builder.max_depth()) return builder.add_leaf(items);
    std::vector<std::uint32_t> below, above;
    for (int k = 0; k < 3; ++k) {
        const int axis = (depth + k) % 3;
        Box box;
        for (std::uint32_t p : items) box.expand(builder.box(p));
        const Real split = (box.min[axis] + box.max[axis]) / 2;
        builder.sort(items, axis, split, below, above);
        if (2 * (below.size() + above.size()) > 3 * items.size()) continue;
        const BspRef left = build_midpoint(builder, below, below_plane(cell, axis, split), depth + 1);
        const BspRef right = build_midpoint(builder, above, above_plane(cell, axis, split), depth + 1);
        return builder.add_inner(axis, split, left, right);
    }
    return builder.add_leaf(items);
