#pragma once
// A sweep: a campaign (campaign.hpp) of one base scene over parameters and seeds (format in
// share/docs/scene-format.md, "Sweeps"). Its cases are every listed case (or the base scene alone)
// at every point of the grid, each value a `--set` override located in the sweep file; each case
// runs with every seed into cases/<name>. Reading is two-pass like a scene's: the sweep's own keys
// first, then every run's scene against the registry.
#include <filesystem>
#include <vector>

#include "frictionlab/base/diagnostics.hpp"
#include "frictionlab/campaign/campaign.hpp"

namespace frictionlab {

class Registry;

/// A sweep is a campaign and nothing more: its grid and listed cases make its cases.
struct Sweep : Campaign {};

/// A case's name in the sweep's tables: its `name:`, else its values (a point of the grid), else
/// `base` (the base scene alone, over seeds).
std::string sweep_case_name(const CampaignCase& c);

/// The sweep's own keys, with file:line:column errors; the base scene is not read yet.
Sweep read_sweep(const std::filesystem::path& file, Diagnostics& diagnostics);

/// Every run: its name (the case's name or values, then its seed), its values and its scene,
/// checked like any scene (errors in an override point at the sweep file), writing into
/// `output/cases/<name>`.
std::vector<CampaignRun> sweep_runs(const Sweep& sweep, const std::filesystem::path& output, const Registry& registry,
                                    Diagnostics& diagnostics);

}  // namespace frictionlab
