#pragma once
// The junction counts per interface block that a friction law with junctions publishes (glossary:
// junctions_pinned, junctions_sliding, junctions_dislocated over "interface"). The laws publish them
// and every observer that reads them finds and checks them here, so the names and the checks exist once.
#include <limits>
#include <optional>
#include <string>
#include <string_view>

#include <Eigen/Core>

#include "frictionlab/model/context.hpp"
#include "frictionlab/model/quantities.hpp"
#include "frictionlab/model/state.hpp"

namespace frictionlab {

struct JunctionCounts {
    static constexpr std::string_view pinned_name = "junctions_pinned";
    static constexpr std::string_view sliding_name = "junctions_sliding";
    static constexpr std::string_view dislocated_name = "junctions_dislocated";

    const Eigen::ArrayXd* pinned = nullptr;      // N_p per block
    const Eigen::ArrayXd* sliding = nullptr;     // N_s per block
    const Eigen::ArrayXd* dislocated = nullptr;  // N_d per block

    /// The three fields as the component built with `ctx` needs them, one value per node of
    /// "interface", declared needed in its name (Quantities::needed_field): a scene where no effect
    /// publishes them is refused at assembly, at that component, with `remedy` (what its user can
    /// change instead). Observers that cannot do without the counts call it from their constructor;
    /// the values are there from the first evaluation on.
    static JunctionCounts need(const Context& ctx, const std::string& remedy = {});
    /// Whether an effect publishes the three fields over "interface" (an observer built after the
    /// effects may choose what it reads by it).
    static bool published(const Quantities& q);
    /// The three fields if the scene publishes them, for observers that only use the counts then.
    static std::optional<JunctionCounts> find(const Quantities& q, Index blocks);

    /// The three fields a friction law with junctions writes, published over `node_set`.
    struct Writable {
        Eigen::ArrayXd *pinned, *sliding, *dislocated;
    };
    static Writable publish(Quantities& q, const std::string& node_set, Index blocks);

    /// N_p / (N_p + N_s + N_d) of block b; NaN for a block without junctions (detached).
    double pinned_fraction(Index b) const {
        const double all = (*pinned)(b) + (*sliding)(b) + (*dislocated)(b);
        return all > 0 ? (*pinned)(b) / all : std::numeric_limits<double>::quiet_NaN();
    }
};

}  // namespace frictionlab
