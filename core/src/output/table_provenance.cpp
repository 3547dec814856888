#include "frictionlab/output/table_provenance.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

namespace frictionlab {

TableProvenance TableProvenance::of(const RunInfo& info) {
    TableProvenance p;
    p.version = info.framework_version;
    p.scene_file = info.scene_file.filename().string();
    p.scene_hash = info.scene_hash;
    p.seed = info.seed;
    for (const auto& plugin : info.plugins)
        p.plugins += fmt::format("{}{} {}", p.plugins.empty() ? "" : ", ", plugin.name, plugin.version);
    return p;
}

std::string table_sidecar_yaml(const TableProvenance& provenance, const std::vector<std::string>& columns) {
    YAML::Emitter y;
    y << YAML::BeginMap;
    y << YAML::Key << "framework" << YAML::Value << provenance.framework;
    y << YAML::Key << "version" << YAML::Value << provenance.version;
    y << YAML::Key << "scene_file" << YAML::Value << provenance.scene_file;
    y << YAML::Key << "scene_hash" << YAML::Value << provenance.scene_hash;
    y << YAML::Key << "seed" << YAML::Value << provenance.seed;
    y << YAML::Key << "plugins" << YAML::Value << provenance.plugins;
    y << YAML::Key << "columns" << YAML::Value << YAML::Flow << columns;
    y << YAML::EndMap;
    return std::string(y.c_str()) + "\n";
}

std::filesystem::path table_sidecar_path(const std::filesystem::path& file) {
    return std::filesystem::path(file).concat(".meta.yaml");
}

}  // namespace frictionlab
