#include "frictionlab/campaign/keys.hpp"

#include "frictionlab/base/param_spec.hpp"

namespace frictionlab::detail {

// Declared like a scene's keys (scene/keys.cpp): one struct per group, the ParamSpec builder.
namespace {

struct Study {
    std::string title, scene;
    double observe_every = 1.0e-6;
    double profile_every = 1.0e-4;
    bool run_failures_again = true;
};

struct StudyCase {
    std::string name, family;
    std::vector<std::string> set;
};

struct Sweep {
    std::string title, scene;
    bool leave_out_disagreeing = false;
};

}  // namespace

const std::vector<ParamInfo>& study_params() {
    static const ParamSpec<Study> spec = [] {
        ParamSpec<Study> s;
        s.add("title", &Study::title, "A line describing the study, for its table and plot.");
        s.add("scene", &Study::scene,
              "The base scene, relative to the study file's folder: settling first, loading last.")
            .required();
        s.add("observe_every", &Study::observe_every,
              "Cadence of the rupture-event detection in every case; it bounds how well the time and F_S of an "
              "event are resolved.")
            .unit("s")
            .greater_than(0);
        s.add("profile_every", &Study::profile_every,
              "Cadence of the interface profiles (forces, slip) in every case; it must divide the settling "
              "stage's duration.")
            .unit("s")
            .greater_than(0);
        s.add("run_failures_again", &Study::run_failures_again,
              "With seeds: run a case that fails the accuracy standard again, with the reference, on as many other "
              "seeds before rejecting it (the standard's rule); false judges on the first ensemble alone, where "
              "the reference's runs are too costly to repeat, and a fail is then unconfirmed.");
        return s;
    }();
    return spec.params();
}

const std::vector<std::string>& study_sections() {
    static const std::vector<std::string> keys = {"seeds", "reference", "half_step", "cases"};
    return keys;
}

const std::vector<ParamInfo>& study_case_params(bool reference) {
    static const ParamSpec<StudyCase> reference_spec = [] {
        ParamSpec<StudyCase> s;
        s.add("set", &StudyCase::set,
              "Overrides of the base scene, key.path=value as with --set, that make the converged run.")
            .required();
        return s;
    }();
    static const ParamSpec<StudyCase> case_spec = [] {
        ParamSpec<StudyCase> s;
        s.add("name", &StudyCase::name, "Name of the case: a-z, 0-9, _, . and -, starting with a letter; unique.")
            .required();
        s.add("family", &StudyCase::family,
              "Curve of the work-precision plot the case belongs to; default: its integrator type.");
        s.add("set", &StudyCase::set,
              "Overrides of the base scene, key.path=value as with --set; absent: the base scene as it is.");
        return s;
    }();
    return reference ? reference_spec.params() : case_spec.params();
}

const std::vector<ParamInfo>& sweep_params() {
    static const ParamSpec<Sweep> spec = [] {
        ParamSpec<Sweep> s;
        s.add("title", &Sweep::title, "A line describing the sweep, for its tables and figures.");
        s.add("scene", &Sweep::scene, "The base scene, relative to the sweep file's folder.").required();
        s.add("leave_out_disagreeing", &Sweep::leave_out_disagreeing,
              "Leave the runs whose rupture events disagree with their own check (theory.md §5a) out of "
              "sweep_statistics.csv; false counts them in, and its `disagreeing` column says how many there are.");
        return s;
    }();
    return spec.params();
}

const std::vector<std::string>& sweep_sections() {
    static const std::vector<std::string> keys = {"seeds", "grid", "cases"};
    return keys;
}

const std::vector<ParamInfo>& sweep_case_params() {
    static const ParamSpec<StudyCase> spec = [] {
        ParamSpec<StudyCase> s;
        s.add("name", &StudyCase::name,
              "Name of the case (a-z, 0-9, _, . and -, starting with a letter); default: its values.");
        s.add("set", &StudyCase::set, "Overrides of the base scene, key.path=value as with --set.").required();
        return s;
    }();
    return spec.params();
}

}  // namespace frictionlab::detail
