#include "frictionlab/campaign/campaign_table.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "frictionlab/base/version.hpp"
#include "frictionlab/campaign/csv_cell.hpp"
#include "frictionlab/campaign/key_unit.hpp"
#include "frictionlab/output/atomic_file.hpp"
#include "frictionlab/output/provenance.hpp"

namespace frictionlab {

std::vector<CampaignColumn> value_columns(const std::vector<CampaignRun>& runs, const Registry& registry) {
    std::vector<CampaignColumn> columns;
    for (const auto& run : runs)
        for (const auto& value : run.values) {
            const std::string& key = value.first;  // not a structured binding: clang 14 cannot capture one
            if (std::none_of(columns.begin(), columns.end(), [&](const auto& c) { return c.name == key; }))
                columns.push_back({key, key_unit(run.scene, registry, key)});
        }
    return columns;
}

CampaignKeys split_varied(const std::vector<CampaignColumn>& columns, const std::vector<CampaignRun>& runs) {
    CampaignKeys out;
    for (const auto& column : columns) {
        std::vector<std::string> seen;
        for (const auto& run : runs) {
            const auto it = std::find_if(run.values.begin(), run.values.end(),
                                         [&](const auto& v) { return v.first == column.name; });
            const std::string value = it == run.values.end() ? std::string() : it->second;
            if (std::find(seen.begin(), seen.end(), value) == seen.end()) seen.push_back(value);
        }
        if (seen.size() > 1)
            out.varied.push_back(column);
        else
            out.constants.emplace_back(column.name, seen.empty() ? std::string() : seen.front());
    }
    return out;
}

std::vector<CampaignColumn> statistic_summary_columns() {
    return {{"statistic", ""},
            {"unit", ""},
            {"n", "1"},
            {"missing", "1"},
            {"mean", unit_of_row},
            {"sd", unit_of_row},
            {"ci_low", unit_of_row},
            {"ci_high", unit_of_row},
            {"interval", ""}};
}

void write_campaign_table(const Campaign& campaign, const std::string& kind, const std::filesystem::path& file,
                          const std::vector<CampaignColumn>& columns, const std::string& rows, const std::string& note,
                          const CampaignKeys* keys) {
    std::vector<std::string> names;
    std::string header;
    for (const auto& c : columns) {
        names.push_back(c.name);
        // fmt, not "," + a temporary string: GCC 12 reports a false -Wrestrict on that.
        header += header.empty() ? csv_cell(c.name) : fmt::format(",{}", csv_cell(c.name));
    }
    YAML::Emitter y;
    y << YAML::BeginMap;
    y << YAML::Key << "framework" << YAML::Value << "frictionlab";
    y << YAML::Key << "version" << YAML::Value << framework_version();
    y << YAML::Key << kind + "_file" << YAML::Value << campaign.file.filename().string();
    y << YAML::Key << "title" << YAML::Value << campaign.title;
    y << YAML::Key << "seeds" << YAML::Value << YAML::Flow << campaign.seeds;
    y << YAML::Key << "note" << YAML::Value << note;
    y << YAML::Key << "columns" << YAML::Value << YAML::Flow << names;
    y << YAML::Key << "units" << YAML::Value << YAML::BeginMap;
    // Quoted, so that "1" reads back as the text of a unit, not as a number.
    for (const auto& c : columns) y << YAML::Key << c.name << YAML::Value << YAML::DoubleQuoted << c.unit;
    y << YAML::EndMap;
    if (keys) {
        std::vector<std::string> varied;
        for (const auto& c : keys->varied) varied.push_back(c.name);
        y << YAML::Key << "varied" << YAML::Value << YAML::Flow << varied;
        y << YAML::Key << "constants" << YAML::Value << YAML::BeginMap;
        for (const auto& [key, value] : keys->constants)
            y << YAML::Key << key << YAML::Value << YAML::DoubleQuoted << value;
        y << YAML::EndMap;
    }
    y << YAML::EndMap;
    write_file_atomically(table_sidecar_path(file), std::string(y.c_str()) + "\n");
    write_file_atomically(file, header + "\n" + rows);
}

}  // namespace frictionlab
