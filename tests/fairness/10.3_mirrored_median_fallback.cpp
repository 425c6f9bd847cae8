// fairness 10.3 pass: the midpoint build mirrored (centres at or above the middle go left) and,
// when every centre falls on one side, the list sorted along the axis before it is halved (a
// median split, where the reference halves the list as it stands): every primitive in one leaf
// and the recursion ends, as the contract asks; the tree differs, the hits do not
// @body
    if (primitives.size() == 1) return builder.primitive(primitives[0]);
    Box box;
    for (std::uint32_t p : primitives) box.expand(builder.box(builder.primitive(p)));
    const Real middle = (box.min[axis] + box.max[axis]) / 2;
    const auto split = std::partition(primitives.begin(), primitives.end(),
                                      [&](std::uint32_t p) { return builder.centre(p)[axis] >= middle; });
    auto left_count = std::size_t(split - primitives.begin());
    if (left_count == 0 || left_count == primitives.size()) {
        left_count = primitives.size() / 2;
        std::nth_element(primitives.begin(), primitives.begin() + std::ptrdiff_t(left_count), primitives.end(),
                         [&](std::uint32_t i, std::uint32_t j) { return builder.centre(i)[axis] < builder.centre(j)[axis]; });
    }
    const int next = (axis + 1) % 3;
    const BvhRef left = build_midpoint(builder, primitives.first(left_count), next);
    const BvhRef right = build_midpoint(builder, primitives.subspan(left_count), next);
    return builder.add_node(left, right);
