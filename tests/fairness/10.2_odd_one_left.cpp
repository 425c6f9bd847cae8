// fairness 10.2 pass: the sorted build with std::nth_element instead of a full sort (the book's
// own suggestion, §10.3), and the odd primitive of an odd count given to the left half instead
// of the right: the same balanced tree up to which half is larger
// @body
    if (primitives.size() == 1) return builder.primitive(primitives[0]);
    const std::size_t half = (primitives.size() + 1) / 2;
    std::nth_element(primitives.begin(), primitives.begin() + std::ptrdiff_t(half), primitives.end(),
                     [&](std::uint32_t i, std::uint32_t j) { return builder.centre(i)[axis] < builder.centre(j)[axis]; });
    const int next = (axis + 1) % 3;
    const BvhRef left = build_sorted(builder, primitives.first(half), next);
    const BvhRef right = build_sorted(builder, primitives.subspan(half), next);
    return builder.add_node(left, right);
