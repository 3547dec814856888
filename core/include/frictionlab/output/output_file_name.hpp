#pragma once
// Observers name their files in the run's output directory. A name with a folder in it ("../x.csv",
// "/tmp/x.csv") would write outside it, where --overwrite and the run's record cannot follow; a
// name of the run's own files (run.yaml, the checkpoints, their temporaries, the marker) would
// replace them, or be replaced by them.
#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "frictionlab/base/param_spec.hpp"

namespace frictionlab {

/// Whether `name`, at the top of an output directory, is one of the run's own files: run.yaml, a
/// checkpoint (checkpoint.*), the output marker, or the temporary of an atomic write (*.tmp).
bool is_run_file(std::string_view name);

/// Why `name` cannot be the file name of an output, or "" if it can: what a ParamSpec rule returns.
std::string output_file_name_problem(const std::string& name);

/// Declares the files and folders an observer writes (`outputs` of its Params) on its spec: each
/// name is checked where its key is written (output_file_name_problem), and the scene check refuses
/// two outputs of one run with the same name (ParamSpec::writes).
template <class P>
void add_outputs(ParamSpec<P>& spec, std::vector<OutputName> (*outputs)(const P&)) {
    spec.writes(outputs);
    std::vector<std::string> keys;
    for (const auto& o : outputs(P{}))
        if (!o.key.empty() && std::find(keys.begin(), keys.end(), o.key) == keys.end()) keys.push_back(o.key);
    for (const auto& key : keys)
        spec.rule(key, [outputs, key](const P& p) {
            for (const auto& o : outputs(p))
                if (o.key == key)
                    if (std::string why = output_file_name_problem(o.name); !why.empty()) return why;
            return std::string();
        });
}

}  // namespace frictionlab
