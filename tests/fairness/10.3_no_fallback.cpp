// fairness 10.3 fail: the course's midpoint build as printed, without the halving: when every
// centre falls on one side (identical boxes), one child gets the whole list again and the
// recursion never ends; the stack overflows and the test program crashes (§10.3 erratum)
// expect: crashed
// @body
    if (primitives.size() == 1) return builder.primitive(primitives[0]);
    Box box;
    for (std::uint32_t p : primitives) box.expand(builder.box(builder.primitive(p)));
    const Real middle = (box.min[axis] + box.max[axis]) / 2;
    const auto split = std::partition(primitives.begin(), primitives.end(),
                                      [&](std::uint32_t p) { return builder.centre(p)[axis] < middle; });
    const auto left_count = std::size_t(split - primitives.begin());
    const int next = (axis + 1) % 3;
    const BvhRef left = build_midpoint(builder, primitives.first(left_count), next);
    const BvhRef right = build_midpoint(builder, primitives.subspan(left_count), next);
    return builder.add_node(left, right);
