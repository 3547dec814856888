#pragma once
// The key paths a campaign's cases set, and each run's value of them from its resolved scene: a
// study's knob columns, a sweep's columns for its listed cases (whose values are not a grid's).
#include <string>
#include <vector>

#include "frictionlab/campaign/campaign.hpp"

namespace frictionlab {

/// `leading`, then every key path the cases' overrides set, each once; one that sets a whole
/// mapping (such as `integrator={type: ..., rtol: ...}`) stands for each of its keys.
std::vector<std::string> set_keys(const Campaign& campaign, const std::vector<CampaignRun>& runs,
                                  std::vector<std::string> leading);

/// Each run's value of every key of `keys` its values do not have yet, as YAML text from its
/// resolved scene ("" where the scene has no such key), appended in the order of `keys`.
void add_values_of(const std::vector<std::string>& keys, std::vector<CampaignRun>& runs);

}  // namespace frictionlab
