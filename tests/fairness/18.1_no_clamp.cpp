// fairness 18.1 fail: open + s (close - open) without keeping it below close: for u just below 1
// in the last stratum, s rounds to 1 and the time is exactly close, outside the shutter's
// [open, close) (the header says rounding must not push it there)
// @body
    const Real s = (Real(k) + u) / Real(n);
    return open + s * (close - open);
