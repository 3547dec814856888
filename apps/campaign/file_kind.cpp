#include "frictionlab/campaign/file_kind.hpp"

#include <yaml-cpp/yaml.h>

#include "campaign_reader.hpp"

namespace frictionlab {

CampaignFileKind campaign_file_kind(const std::filesystem::path& file) {
    // Only a regular file of sensible size is opened here (a FIFO would block, /dev/zero never
    // end); anything else is left to the scene reader, which refuses it with the reason.
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec) ||
        std::filesystem::file_size(file, ec) > detail::largest_campaign_file || ec)
        return CampaignFileKind::scene;
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
