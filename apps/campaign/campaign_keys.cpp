#include "frictionlab/campaign_keys.hpp"

#include "frictionlab/scene/keys.hpp"

namespace frictionlab::detail {

const std::vector<ParamInfo>& study_params() {
    static const std::vector<ParamInfo> params = {
        key("title", ValueType::string, std::string(), "A line describing the study, for its table and plot."),
        required(key("scene", ValueType::string, std::string(),
                     "The base scene, relative to the study file's folder: settling first, loading last.")),
        greater_than(key("observe_every", ValueType::real, 1.0e-6,
                         "Cadence of the rupture-event detection in every case; it bounds how well the time "
                         "and F_S of an event are resolved.", "s"),
                     0),
        greater_than(key("profile_every", ValueType::real, 1.0e-4,
                         "Cadence of the interface profiles (forces, slip) in every case; it must divide the "
                         "settling stage's duration.", "s"),
                     0),
    };
    return params;
}

const std::vector<std::string>& study_sections() {
    static const std::vector<std::string> keys = {"reference", "cases"};
    return keys;
}

const std::vector<ParamInfo>& study_case_params(bool reference) {
    static const std::vector<ParamInfo> reference_params = {
        required(key("set", ValueType::string_list, std::vector<std::string>(),
                     "Overrides of the base scene, key.path=value as with --set, that make the converged run.")),
    };
    static const std::vector<ParamInfo> case_params = {
        required(key("name", ValueType::string, std::string(),
                     "Name of the case: a-z, 0-9, _, . and -, starting with a letter; unique.")),
        key("family", ValueType::string, std::string(),
            "Curve of the work-precision plot the case belongs to; default: its integrator type."),
        key("set", ValueType::string_list, std::vector<std::string>(),
            "Overrides of the base scene, key.path=value as with --set; absent: the base scene as it is."),
    };
    return reference ? reference_params : case_params;
}

const std::vector<ParamInfo>& sweep_params() {
    static const std::vector<ParamInfo> params = {
        key("title", ValueType::string, std::string(), "A line describing the sweep, for its tables and figures."),
        required(key("scene", ValueType::string, std::string(),
                     "The base scene, relative to the sweep file's folder.")),
        key("seeds", ValueType::real_list, std::vector<double>(),
            "Seeds each case runs with (whole numbers >= 0); absent: the base scene's seed only."),
    };
    return params;
}

const std::vector<std::string>& sweep_sections() {
    static const std::vector<std::string> keys = {"grid", "cases"};
    return keys;
}

const std::vector<ParamInfo>& sweep_case_params() {
    static const std::vector<ParamInfo> params = {
        key("name", ValueType::string, std::string(),
            "Name of the case (a-z, 0-9, _, . and -, starting with a letter); default: its values."),
        required(key("set", ValueType::string_list, std::vector<std::string>(),
                     "Overrides of the base scene, key.path=value as with --set.")),
    };
    return params;
}

}  // namespace frictionlab::detail
