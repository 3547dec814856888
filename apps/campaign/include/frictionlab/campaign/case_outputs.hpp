#pragma once
// Where a case's observers wrote what a campaign collects, read from the observers' resolved
// parameters (a user may rename `precursors.events_file`), never from fixed file names.
#include <filesystem>
#include <optional>

#include "frictionlab/scene/scene.hpp"

namespace frictionlab {

struct RuptureFiles {
    std::filesystem::path events;   // one row per rupture event (precursors.events_file)
    std::filesystem::path summary;  // YAML summary with the global static coefficient (precursors.summary_file)
};

/// The files of the scene's `precursors` observer, in its output directory; nothing if it has none.
std::optional<RuptureFiles> rupture_files(const Scene& scene);

}  // namespace frictionlab
