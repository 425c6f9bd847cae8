// fairness 15.1 pass: Fisher-Yates run from the front (item i trades places with one of items
// i..n-1): as uniform as the reference's loop from the back, though it draws other numbers, so
// the orders differ shuffle by shuffle but not in distribution
// @body
    const std::size_t n = order.size();
    for (std::size_t i = 0; i + 1 < n; ++i) {
        const std::size_t j = i + random(std::uint32_t(n - i));
        std::swap(order[i], order[j]);
    }
