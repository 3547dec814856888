#include "frictionlab/campaign_file.hpp"

#include <yaml-cpp/yaml.h>

namespace frictionlab {

CampaignFileKind campaign_file_kind(const std::filesystem::path& file) {
    try {
        const YAML::Node root = YAML::LoadFile(file.string());
        if (!root.IsMap()) return CampaignFileKind::scene;
        if (root["reference"]) return CampaignFileKind::study;
        if (root["grid"] || root["seeds"] || root["cases"]) return CampaignFileKind::sweep;
    } catch (const YAML::Exception&) {
        // The scene reader reports the malformed YAML with its location.
    }
    return CampaignFileKind::scene;
}

}  // namespace frictionlab
