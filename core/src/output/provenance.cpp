#include "frictionlab/output/provenance.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

namespace frictionlab {

Provenance Provenance::of(const RunInfo& info) {
    Provenance p;
    p.version = info.framework_version;
    p.scene_file = info.scene_file.filename().string();
    p.scene_hash = info.scene_hash;
    p.seed = info.seed;
    for (const auto& plugin : info.plugins)
        p.plugins += fmt::format("{}{} {}", p.plugins.empty() ? "" : ", ", plugin.name, plugin.version);
    return p;
}

namespace {
/// Each line of `text` indented by `indent` spaces, each ending in a newline.
std::string indented(const std::string& text, int indent) {
    std::string out;
    for (std::size_t start = 0; start < text.size();) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        out += std::string(indent, ' ') + text.substr(start, end - start) + "\n";
        start = end + 1;
    }
    return out;
}
}  // namespace

std::string Provenance::yaml(int indent) const {
    YAML::Emitter y;
    y << YAML::BeginMap;
    const auto entry = [&](const char* key, const auto& value) { y << YAML::Key << key << YAML::Value << value; };
    visit(entry, entry);
    y << YAML::EndMap;
    return indented(y.c_str(), indent);
}

std::vector<std::string> units_of(const std::vector<std::string>& columns, const ColumnTypes& types) {
    std::vector<std::string> out;
    for (const auto& c : columns) {
        const auto unit = types.units.find(c);
        out.push_back(unit == types.units.end() ? "" : unit->second);
    }
    return out;
}

std::string table_sidecar_yaml(const Provenance& provenance, const std::vector<std::string>& columns,
                               const ColumnTypes& types) {
    const auto list = [](const char* key, const std::vector<std::string>& names) {
        YAML::Emitter y;
        y << YAML::Flow << names;
        return std::string(key) + ": " + y.c_str() + "\n";
    };
    std::string out = provenance.yaml() + list("columns", columns);
    const std::vector<std::string> units = units_of(columns, types);
    YAML::Emitter y;
    y << YAML::BeginMap;
    // Quoted, so that "1" reads back as the text of a unit, not as a number.
    for (std::size_t k = 0; k < columns.size(); ++k)
        y << YAML::Key << columns[k] << YAML::Value << YAML::DoubleQuoted << units[k];
    y << YAML::EndMap;
    out += "units:\n" + indented(y.c_str(), 2);
    if (!types.integers.empty()) out += list("integer_columns", types.integers);
    if (!types.flags.empty()) out += list("flag_columns", types.flags);
    return out;
}

std::filesystem::path table_sidecar_path(const std::filesystem::path& file) {
    return std::filesystem::path(file).concat(".meta.yaml");
}

}  // namespace frictionlab
