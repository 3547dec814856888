#include "frictionlab/campaign/file_kind.hpp"

#include <fstream>
#include <iterator>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

namespace frictionlab {

namespace {
constexpr std::uintmax_t largest_file = 4 * 1024 * 1024;  // as for scenes
}  // namespace

CampaignFileKind campaign_file_kind(const std::filesystem::path& file) {
    // Only a regular file of sensible size is opened here (a FIFO would block, /dev/zero never
    // end); anything else is left to the scene reader, which refuses it with the reason.
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec) || std::filesystem::file_size(file, ec) > largest_file || ec)
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

std::optional<std::string> read_campaign_text(const std::filesystem::path& file, const char* what,
                                              Diagnostics& diagnostics) {
    std::error_code ec;
    const auto fail = [&](const std::string& why) {
        diagnostics.error({file.string(), 0, 0}, "", fmt::format("cannot read the {} file: {}", what, why));
        return std::nullopt;
    };
    if (!std::filesystem::is_regular_file(file, ec))
        return fail(std::filesystem::exists(file, ec) ? "it is not a file" : "it does not exist");
    if (std::filesystem::file_size(file, ec) > largest_file) return fail("it is larger than 4 MiB");
    std::ifstream in(file, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace frictionlab
