// A planted bug (book §15.2): a shuffle that leaves every order as it was, so each sample's
// light stratum is its pixel stratum. Chapter 15's statistical test must catch it. The
// chapter's other exercises are the reference ones: the solution file is included with its
// fisher_yates renamed out of the way.
#include "core/sampler.hpp"
#include "shading/light.hpp"

#define fisher_yates fisher_yates_as_written
#include "../../solutions/ch15_soft_shadows.cpp"
#undef fisher_yates

namespace rt {
void fisher_yates(std::vector<std::uint32_t>&, pcg32&) {}
}  // namespace rt
