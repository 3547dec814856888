#pragma once
// A campaign: one base scene run as several cases, each case with every seed. A case is a set of
// `--set` overrides located in the campaign file; a run is a case with one seed, an ordinary scene
// that the runner (runner.hpp) runs into a directory of its own. The runs of one case over the
// seeds are that case's ensemble, what statistics over seeds are taken of. A sweep (sweep.hpp) and
// an accuracy study (study.hpp) are campaigns; each decides its cases and where its runs write.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "frictionlab/base/diagnostics.hpp"
#include "frictionlab/scene/scene.hpp"

namespace frictionlab {

class Registry;

/// Key path (or "seed") and value as written: what sets a case or run apart, in column order.
using CampaignValues = std::vector<std::pair<std::string, std::string>>;

/// One case: the base scene with overrides, each located in the campaign file.
struct CampaignCase {
    std::string name;
    SourceLocation where;
    std::vector<SceneOverride> overrides;
    CampaignValues values;  // a sweep's varied values; a study's cases are told apart by name
};

struct CampaignRun;

/// What every campaign file declares, and its cases.
struct Campaign {
    std::filesystem::path file;
    std::string title;
    std::filesystem::path scene;  // the base scene, resolved against the campaign file's folder
    SourceLocation scene_where;
    std::vector<std::int64_t> seeds;  // empty: the base scene's own seed only
    SourceLocation seeds_where;
    std::vector<CampaignCase> cases;  // in the order their runs come
    /// A sweep's statistics leave out the runs whose events disagree with their own check.
    bool leave_out_disagreeing = false;

    /// Every case with every seed (none where `seeds` is empty: the base scene's own), case by
    /// case, so that a case's runs are adjacent. Their names, values and scenes are left to the
    /// kind of campaign, which knows where its runs write.
    std::vector<CampaignRun> runs() const;
};

/// One run: a case with one seed, its scene checked and writing into the run's own directory.
struct CampaignRun {
    std::size_t case_index = 0;        // into Campaign::cases
    std::optional<std::int64_t> seed;  // none: the base scene's own
    std::string name;                  // unique; its log is logs/<name>.log
    CampaignValues values;
    Scene scene;
};

/// The base scene alone, checked before any run so that its own errors are reported once, not
/// once per run; nothing if it has errors.
std::optional<Scene> base_scene(const Campaign& campaign, const Registry& registry, Diagnostics& diagnostics);

/// The base scene with the case's overrides, the seed (located at the campaign's `seeds:`) and
/// `extra` (where the run writes, what it observes), checked like any scene: an error in an
/// override points at the campaign file. Nothing if it has errors.
std::optional<Scene> run_scene(const Campaign& campaign, const CampaignCase& c, std::optional<std::int64_t> seed,
                               const std::vector<SceneOverride>& extra, const Registry& registry,
                               Diagnostics& diagnostics);

}  // namespace frictionlab
