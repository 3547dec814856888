#pragma once
// Which kind of YAML file a user hands to `check` or `plot`: a scene, an accuracy study or a sweep.
#include <filesystem>

namespace frictionlab {

enum class CampaignFileKind { scene, study, sweep };

/// A study has `reference:`; a sweep has `grid:`, `seeds:` or `cases:` without a reference; any
/// other file (or one that does not parse) is read as a scene, whose reader reports its errors.
CampaignFileKind campaign_file_kind(const std::filesystem::path& file);

}  // namespace frictionlab
