// fairness 15.1 fail: the naive shuffle that swaps item i with any of the n items, not only with
// items 0..i: n^n equally likely runs cannot spread evenly over n! orders, so some orders come
// out more often than others (§15.2)
// @body
    const auto n = std::uint32_t(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) std::swap(order[i], order[random(n)]);
