#pragma once
// Which kind of YAML file a user hands to `check` or `plot`: a scene, an accuracy study or a sweep.
#include <filesystem>
#include <optional>
#include <string>

#include "frictionlab/base/diagnostics.hpp"

namespace frictionlab {

enum class CampaignFileKind { scene, study, sweep };

/// A study has `reference:`; a sweep has `grid:`, `seeds:` or `cases:` without a reference; any
/// other file (or one that does not parse) is read as a scene, whose reader reports its errors.
CampaignFileKind campaign_file_kind(const std::filesystem::path& file);

/// The text of a study or sweep file (`what`: "study", "sweep"): a regular file of at most 4 MiB,
/// as scenes are read; anything else is reported to `diagnostics` and gives nothing.
std::optional<std::string> read_campaign_text(const std::filesystem::path& file, const char* what,
                                              Diagnostics& diagnostics);

}  // namespace frictionlab
