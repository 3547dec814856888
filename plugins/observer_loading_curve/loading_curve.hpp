#pragma once
#include <memory>

#include "frictionlab/output/csv_table.hpp"
#include "frictionlab/model/kinds.hpp"
#include "frictionlab/base/param_spec.hpp"
#include "frictionlab/simulation/run.hpp"

namespace frictionlab {

/// The loading curve of Li et al. (2020) Fig. 6: the driving force F_S(t) (Eq. 4), F_S/F_N, and the
/// interface's totals, one CSV row per observation. Columns whose quantity no effect of the scene
/// publishes are left out (a scene without friction has no friction column).
class LoadingCurve final : public Observer {
public:
    // Checkpoints: it keeps nothing but its tables, which the run cuts back and appends to.
    bool checkpointable() const override { return true; }
    struct Params {
        std::string file = "loading_curve.csv";
    };
    static constexpr std::string_view type = "loading_curve";
    static ParamSpec<Params> spec();

    LoadingCurve(const Params& p, const Context&);
    void begin(const RunView& view) override;
    void observe(const RunView& view) override;

private:
    struct Column {
        std::string name;
        const double* scalar = nullptr;         // a published scalar, or
        const Eigen::ArrayXd* field = nullptr;  // the sum of a published field
    };
    Params params_;
    std::vector<Column> columns_;
    const double* normal_load_ = nullptr;
    const double* driving_force_ = nullptr;
    std::unique_ptr<TableWriter> table_;
    std::vector<double> row_;
};

}  // namespace frictionlab
