#pragma once
#include <functional>
#include <memory>
#include <vector>

#include "frictionlab/output/table_writer.hpp"
#include "frictionlab/model/kinds.hpp"
#include "frictionlab/base/param_spec.hpp"
#include "frictionlab/simulation/run.hpp"

namespace frictionlab {

/// The whole interface against time, one row per observation and one column per interface block
/// (ordered by x): the data of a space-time map, the way experiments show rupture fronts (Rubinstein
/// et al. 2004; Ben-David et al. 2010). Writes
///   interface_velocity.csv         v_x of each block (m/s)
///   interface_slip.csv             x - x0 of each block (m)
///   interface_pinned_fraction.csv  N_p / (N_p + N_s + N_d) of each block (NaN without junctions),
///                                  when the friction law publishes junction counts
///   interface_normal_force.csv     normal_force of each block (N), when the scene publishes it
///   interface_friction_force.csv   friction_force of each block (N), when the friction law publishes it
///   interface_shear_ratio.csv      friction_force / normal_force of each block, when both exist
/// and on a 2D interface (a 3D body's base), whose blocks form a grid:
///   interface_velocity_y.csv       v_y of each block, across the sliding direction (m/s)
///   interface_slip_y.csv           y - y0 of each block (m)
///   interface_blocks.csv           each block's column (block), node and reference place (x0, y0),
///                                  a row per block, so that a row of any table above is a 2D map
/// (or interface_*.h5 with `format: hdf5`). Rows cost a pass over the interface at the observer's cadence; nothing in
/// between.
class InterfaceHistory final : public Observer {
public:
    // Checkpoints: it keeps nothing but its tables, which the run cuts back and appends to.
    bool checkpointable() const override { return params_.format == TableFormat::csv; }
    struct Params {
        std::string node_set = "interface";
        TableFormat format = TableFormat::csv;
    };
    static constexpr std::string_view type = "interface_history";
    static ParamSpec<Params> spec();

    InterfaceHistory(const Params& p, const Context&);
    void begin(const RunView& view) override;
    void observe(const RunView& view) override;

private:
    using AddTable = std::function<void(const char* file, const std::string& unit,
                                        std::function<double(const RunView&, Index block)> value)>;
    /// The across components and the blocks' places, on a 2D interface.
    void add_across(const RunView& view, const AddTable& add);

    struct Table {
        std::unique_ptr<TableWriter> writer;
        std::function<double(const RunView&, Index block)> value;
    };
    Params params_;
    std::vector<Index> nodes_;
    std::vector<Table> tables_;
    std::vector<double> row_;
};

}  // namespace frictionlab
