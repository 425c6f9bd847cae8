// fairness 8.3 fail: light lost in proportion to the distance instead of exponentially
// 1 - (1 - a) s agrees with a^s at s = 0 and s = 1 only; Beer's law is a power.
// @body
    return Color(1) - (Color(1) - attenuation) * static_cast<float>(distance);
