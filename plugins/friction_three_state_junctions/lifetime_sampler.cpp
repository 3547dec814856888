#include "lifetime_sampler.hpp"

#include "frictionlab/model/random.hpp"

namespace frictionlab {

double LifetimeSampler::sliding(std::uint64_t block, std::uint64_t id, std::uint64_t& counter) const {
    const random::Key key{seed_, block, id, random::Purpose::sliding_time};
    return random::truncated_normal(key, counter, sliding_.mean, sliding_.sd, 0.0);
}

double LifetimeSampler::dislocated(std::uint64_t block, std::uint64_t id, std::uint64_t& counter) const {
    const random::Key key{seed_, block, id, random::Purpose::dislocated_time};
    return random::truncated_normal(key, counter, dislocated_.mean, dislocated_.sd, 0.0);
}

}  // namespace frictionlab
