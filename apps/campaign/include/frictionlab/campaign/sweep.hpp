#pragma once
// A sweep: one base scene run over parameters and seeds (format in share/docs/scene-format.md,
// "Sweeps"). Its cases are every listed case (or the base scene alone) times every combination of
// the grid times every seed, each value a `--set` override located in the sweep file. Reading is
// two-pass like a scene's: the sweep's own keys first, then every case's scene against the registry.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "frictionlab/campaign/case_record.hpp"
#include "frictionlab/base/diagnostics.hpp"
#include "frictionlab/scene/scene.hpp"

namespace frictionlab {

class Registry;

/// One varied key and the values it takes, each value an override `key=value`.
struct SweepAxis {
    std::string key;
    std::vector<SceneOverride> values;
};

struct SweepCase {
    std::string name;  // empty: named by its values
    SourceLocation where;
    std::vector<SceneOverride> overrides;
};

struct Sweep {
    std::filesystem::path file;
    std::string title;
    std::filesystem::path scene;  // resolved against the sweep file's folder
    SourceLocation scene_where;
    std::vector<std::int64_t> seeds;  // empty: the base scene's seed
    SourceLocation seeds_where;
    std::vector<SweepAxis> grid;   // in file order
    std::vector<SweepCase> cases;  // empty: the base scene as one case
};

/// The sweep's own keys, with file:line:column errors; the base scene is not read yet.
Sweep read_sweep(const std::filesystem::path& file, Diagnostics& diagnostics);

/// Every case: its name (from its values unless the listed case names it), its values and its
/// scene, checked like any scene (errors in an override point at the sweep file), writing into
/// `output/cases/<name>`.
std::vector<CampaignCase> sweep_cases(const Sweep& sweep, const std::filesystem::path& output, const Registry& registry,
                                      Diagnostics& diagnostics);

}  // namespace frictionlab
