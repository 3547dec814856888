#include "campaign_reader.hpp"

#include <cmath>
#include <fstream>
#include <iterator>
#include <regex>

#include <fmt/format.h>

namespace frictionlab::detail {

namespace {

std::optional<std::string> read_text(const std::filesystem::path& file, const std::string& what,
                                     Diagnostics& diagnostics) {
    std::error_code ec;
    const auto fail = [&](const std::string& why) {
        diagnostics.error({file.string(), 0, 0}, "", fmt::format("cannot read the {} file: {}", what, why));
        return std::nullopt;
    };
    if (!std::filesystem::is_regular_file(file, ec))
        return fail(std::filesystem::exists(file, ec) ? "it is not a file" : "it does not exist");
    if (std::filesystem::file_size(file, ec) > largest_campaign_file) return fail("it is larger than 4 MiB");
    std::ifstream in(file, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

std::optional<YAML::Node> read_campaign_yaml(const std::filesystem::path& file, const std::string& what,
                                             const std::string& expected, Diagnostics& diagnostics) {
    const auto text = read_text(file, what, diagnostics);
    if (!text) return std::nullopt;
    auto root = read_yaml(*text, file.string(), diagnostics);
    if (root && (!root->IsDefined() || root->IsNull())) {
        diagnostics.error({file.string(), 1, 1}, "", fmt::format("the {} is empty; expected {}", what, expected));
        return std::nullopt;
    }
    return root;
}

std::string flow_text(const YAML::Node& node) {
    if (node.IsScalar()) return node.Scalar();
    YAML::Emitter out;
    out.SetMapFormat(YAML::Flow);
    out.SetSeqFormat(YAML::Flow);
    out << node;
    return out.c_str();
}

Section CampaignReader::read_top(const YAML::Node& root, const SectionKeys& keys, Campaign& campaign) const {
    const auto top = read_section({YAML::Node(YAML::NodeType::Undefined), root}, "", keys, reporter_);
    if (!root.IsMap()) return top;
    campaign.title = value_or(top, "title", std::string());
    if (const auto scene = given(top, "scene"); scene && top.values.contains("scene")) {
        campaign.scene = campaign.file.parent_path() / std::get<std::string>(top.values.at("scene"));
        campaign.scene_where = reporter_.where(scene->site());
    }
    if (const auto seeds = given(top, "seeds")) {
        campaign.seeds_where = reporter_.where(seeds->site());
        campaign.seeds = read_seeds(*seeds);
    }
    return top;
}

std::vector<Entry> CampaignReader::case_items(const Entry& list) const {
    if (!list.value.IsSequence() || list.value.size() == 0) {
        reporter_.error(list.site(), "cases",
                        "expected a non-empty list of cases, got " +
                            (list.value.IsSequence() ? std::string("an empty list") : describe(list.value)));
        return {};
    }
    std::vector<Entry> items;
    for (const auto& item : list.value) items.push_back({YAML::Node(YAML::NodeType::Undefined), item});
    return items;
}

Section CampaignReader::read_case(const Entry& entry, const std::string& path, const SectionKeys& keys,
                                  CampaignCase& c) const {
    c.where = reporter_.where(entry.site());
    const auto s = read_section(entry, path, keys, reporter_);
    c.name = value_or(s, "name", std::string());
    if (const auto set = given(s, "set"); set && s.values.contains("set"))
        for (const auto& item : set->value) {
            // An override's errors point at its first character: after the quote of a quoted scalar.
            SourceLocation at = reporter_.where(item);
            if (is_quoted(item) && at.column > 0) ++at.column;
            c.overrides.push_back({item.Scalar(), at});
        }
    return s;
}

bool CampaignReader::check_name_rule(const CampaignCase& c, const std::string& path) const {
    static const std::regex name_rule("[a-z][a-z0-9_.-]*");
    if (std::regex_match(c.name, name_rule)) return true;
    reporter_.error(c.where, join_path(path, "name"),
                    "expected a name of a-z, 0-9, _, . and -, starting with a letter, got " + quote(c.name));
    return false;
}

std::optional<Entry> CampaignReader::given(const Section& section, const std::string& key) {
    const auto it = section.given.find(key);
    if (it == section.given.end()) return std::nullopt;
    return it->second;
}

std::vector<std::int64_t> CampaignReader::read_seeds(const Entry& entry) const {
    static const std::string expected =
        "expected a list of whole numbers >= 0, a count N (seeds 1 to N) or a range FIRST..LAST";
    // Above 2^53 a double no longer holds every whole number.
    const auto whole = [](const std::string& text) -> std::optional<std::int64_t> {
        static const std::regex digits("[0-9]{1,15}");
        if (!std::regex_match(text, digits)) return std::nullopt;
        return std::stoll(text);
    };
    std::vector<std::int64_t> seeds;
    const YAML::Node& value = entry.value;
    if (value.IsScalar()) {
        static const std::regex range("([0-9]{1,15})\\.\\.([0-9]{1,15})");
        std::smatch m;
        const std::string text = value.Scalar();
        std::int64_t first = 1, last = 0;
        if (const auto count = whole(text)) {
            last = *count;
        } else if (std::regex_match(text, m, range)) {
            first = std::stoll(m[1]), last = std::stoll(m[2]);
        } else {
            reporter_.error(entry.site(), "seeds", expected + ", got " + quote(text));
            return seeds;
        }
        if (last < first || last - first >= 100000) {
            reporter_.error(entry.site(), "seeds", "expected from 1 to 100000 seeds, got " + quote(text));
            return seeds;
        }
        for (std::int64_t s = first; s <= last; ++s) seeds.push_back(s);
        return seeds;
    }
    if (!value.IsSequence()) {
        reporter_.error(entry.site(), "seeds", expected + ", got " + describe(value));
        return seeds;
    }
    if (value.size() == 0) {
        reporter_.error(entry.site(), "seeds", "expected a non-empty list of seeds, got an empty list");
        return seeds;
    }
    for (std::size_t i = 0; i < value.size(); ++i) {
        const auto seed = value[i].IsScalar() ? whole(value[i].Scalar()) : std::nullopt;
        if (!seed) {
            reporter_.error(value[i], index_path("seeds", i),
                            "expected a whole number >= 0, got " +
                                quote(value[i].IsScalar() ? value[i].Scalar() : describe(value[i])));
            continue;
        }
        seeds.push_back(*seed);
    }
    return seeds;
}

}  // namespace frictionlab::detail
