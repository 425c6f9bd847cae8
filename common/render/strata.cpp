#include "render/strata.hpp"

namespace rt {

Vec2 sample_square(Sampler& sampler, Dimension d) {
    if (!sampler.take_stratum(d)) return sampler.get2(d);  // random, or not the sample's first
    const int k = sampler.stratum(d);                      // shuffles first: the order does not depend on the place
    return stratified_point(k, sampler.side(), sampler.strata() == Strata::centres ? Vec2(Real(0.5)) : sampler.get2(d));
}

LineSample sample_line(Sampler& sampler, Dimension d) {
    if (!sampler.take_stratum(d)) return {0, 1, sampler.get1(d)};
    const int k = sampler.stratum(d);
    return {k, sampler.count(), sampler.strata() == Strata::centres ? Real(0.5) : sampler.get1(d)};
}

CameraSample camera_sample(int i, int j, PixelFilter filter, Sampler& sampler) {
    const Vec2 corner{Real(i), Real(j)};
    if (at_centre(sampler.count(), sampler.strata(), filter)) return {corner + Vec2(Real(0.5))};
    const Vec2 u = sample_square(sampler, Dimension::pixel);
    if (filter == PixelFilter::box) return {corner + u};
    return {corner + Vec2(Real(0.5)) + Vec2(tent_offset(u.x), tent_offset(u.y))};
}

}  // namespace rt
