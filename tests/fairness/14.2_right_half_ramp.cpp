// fairness 14.2 fail: the right half inverted as if its distribution were (1 + x^2) / 2, giving
// sqrt(2u - 1): still monotone and still in [-1, 1), but its density rises towards the edge
// instead of falling, so the right half of the tent is a ramp the wrong way (§14.3)
// @body
    return u < Real(0.5) ? std::sqrt(2 * u) - 1 : std::sqrt(2 * u - 1);
