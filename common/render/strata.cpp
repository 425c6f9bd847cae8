#include "render/strata.hpp"

#include "render/antialiasing.hpp"

namespace rt {

Vec2 sample_square(Sampler& sampler, Dimension d) {
    if (!sampler.take_stratum(d)) return sampler.get2(d);  // random, or not the sample's first
    switch (sampler.strata()) {
        case Strata::none:
            break;
        case Strata::centres:
            return stratified_point(sampler.stratum(d), sampler.side(), Vec2(Real(0.5)));
        case Strata::jittered: {
            const int k = sampler.stratum(d);  // shuffles first: the order does not depend on u
            return stratified_point(k, sampler.side(), sampler.get2(d));
        }
    }
    return sampler.get2(d);
}

LineSample sample_line(Sampler& sampler, Dimension d) {
    if (!sampler.take_stratum(d)) return {0, 1, sampler.get1(d)};
    switch (sampler.strata()) {
        case Strata::none:
            break;
        case Strata::centres:
            return {sampler.stratum(d), sampler.count(), Real(0.5)};
        case Strata::jittered: {
            const int k = sampler.stratum(d);
            return {k, sampler.count(), sampler.get1(d)};
        }
    }
    return {0, 1, sampler.get1(d)};
}

}  // namespace rt
