#pragma once
// What the readers of sweep and study files share (share/docs/scene-format.md, "Sweeps" and
// "Accuracy studies"): reading the file, its title, base scene and seeds, and its lists of cases,
// each error at its line and column. Each reader adds its own keys.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "frictionlab/base/diagnostics.hpp"
#include "frictionlab/campaign/campaign.hpp"
#include "frictionlab/scene/values.hpp"
#include "frictionlab/scene/yaml.hpp"

namespace frictionlab::detail {

/// Campaign files are read as scenes are: regular files of at most this size.
inline constexpr std::uintmax_t largest_campaign_file = 4 * 1024 * 1024;

/// The YAML of a campaign file (`what`: "sweep" or "study"); nothing, with the reason in
/// `diagnostics`, if it cannot be read or parsed, or if it is empty (`expected`: what it should hold).
std::optional<YAML::Node> read_campaign_yaml(const std::filesystem::path& file, const std::string& what,
                                             const std::string& expected, Diagnostics& diagnostics);

/// A value of a campaign file or of a resolved scene as one line of text: a scalar as written, a
/// mapping or list in flow style.
std::string flow_text(const YAML::Node& node);

class CampaignReader {
public:
    CampaignReader(const SourceMap& sources, Diagnostics& diagnostics) : reporter_(sources, diagnostics) {}

    /// The top-level mapping read against `keys`; its title, scene (against the folder of
    /// `campaign.file`) and seeds go into `campaign`.
    Section read_top(const YAML::Node& root, const SectionKeys& keys, Campaign& campaign) const;

protected:
    /// The items of `cases:`, a non-empty list; an error and none otherwise.
    std::vector<Entry> case_items(const Entry& list) const;
    /// A case's mapping read against `keys`; its `name` and `set` go into `c`.
    Section read_case(const Entry& entry, const std::string& path, const SectionKeys& keys, CampaignCase& c) const;
    /// False, after an error, unless the case's name is of a-z, 0-9, _, . and -, starting with a letter.
    bool check_name_rule(const CampaignCase& c, const std::string& path) const;

    static std::optional<Entry> given(const Section& section, const std::string& key);
    template <class T>
    static T value_or(const Section& section, const std::string& key, T fallback) {
        const auto it = section.values.find(key);
        return it == section.values.end() ? fallback : std::get<T>(it->second);
    }

    Reporter reporter_;

private:
    std::vector<std::int64_t> read_seeds(const Entry& entry) const;
};

/// A campaign file read by `Reader`, a CampaignReader that names its top-level keys (keys()) and
/// reads those beyond the shared ones (read_own()); a `Kind` that knows only its file if the file
/// cannot be read.
template <class Kind, class Reader>
Kind read_campaign_file(const std::filesystem::path& file, const std::string& what, const std::string& expected,
                        Diagnostics& diagnostics) {
    Kind campaign;
    campaign.file = file;
    const auto root = read_campaign_yaml(file, what, expected, diagnostics);
    if (!root) return campaign;
    const SourceMap sources(file.string());
    Reader reader(sources, diagnostics);
    const auto top = reader.read_top(*root, Reader::keys(), campaign);
    if (root->IsMap()) reader.read_own(*root, top, campaign);
    return campaign;
}

}  // namespace frictionlab::detail
