#include "frictionlab/scene/scene.hpp"

#include <iterator>

#include <fmt/format.h>

#include "frictionlab/base/bounded_file.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "scene/overrides.hpp"
#include "scene/validator.hpp"
#include "frictionlab/scene/yaml.hpp"

namespace frictionlab {

namespace {
struct SceneData {
    std::optional<YAML::Node> root;  // none when the file could not be read or is malformed
    detail::SourceMap sources;
    std::filesystem::path folder;  // that relative plugin paths are taken from
};
}  // namespace

struct SceneDocument::Impl {
    SceneData data;
};

SceneDocument::SceneDocument(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
SceneDocument::SceneDocument(SceneDocument&&) noexcept = default;
SceneDocument& SceneDocument::operator=(SceneDocument&&) noexcept = default;
SceneDocument::~SceneDocument() = default;

namespace {

// Bad input is reported, never thrown; anything else escaping is a bug, still reported rather
// than thrown so that a command can print every diagnostic it has.
template <class F>
void reporting_failures(const std::string& file, Diagnostics& diagnostics, F&& f) {
    try {
        f();
    } catch (const std::exception& e) {
        diagnostics.error({file, 0, 0}, "", std::string("unexpected failure while reading the scene: ") + e.what());
    }
}

/// Far above any scene (the shipped ones are a few kB), far below what would exhaust memory.
constexpr std::uintmax_t largest_scene_file = 4 * 1024 * 1024;

std::optional<std::string> read_file(const std::filesystem::path& file, Diagnostics& diagnostics) {
    auto read = read_bounded_file(file, largest_scene_file, "a scene file");
    if (!read.text) diagnostics.error({file.string(), 0, 0}, "", "cannot read the scene file: " + read.problem);
    return std::move(read.text);
}

std::vector<SceneOverride> from_command_line(const std::vector<std::string>& texts) {
    std::vector<SceneOverride> overrides;
    for (const auto& text : texts) overrides.push_back({text});
    return overrides;
}

SceneData read(const std::optional<std::string>& text, const std::string& name, const std::filesystem::path& folder,
               const std::vector<SceneOverride>& overrides, Diagnostics& diagnostics) {
    SceneData data{std::nullopt, detail::SourceMap(name), folder};
    if (!text) return data;
    reporting_failures(name, diagnostics, [&] {
        data.root = detail::read_yaml(*text, name, diagnostics);
        if (data.root) detail::apply_overrides(*data.root, overrides, data.sources, diagnostics);
    });
    return data;
}

}  // namespace

SceneDocument SceneDocument::load(const std::filesystem::path& file, const std::vector<std::string>& overrides,
                                  Diagnostics& diagnostics) {
    return load_located(file, from_command_line(overrides), diagnostics);
}

SceneDocument SceneDocument::load_located(const std::filesystem::path& file,
                                          const std::vector<SceneOverride>& overrides, Diagnostics& diagnostics) {
    auto data = read(read_file(file, diagnostics), file.string(), file.parent_path(), overrides, diagnostics);
    return SceneDocument(std::make_unique<Impl>(Impl{std::move(data)}));
}

SceneDocument SceneDocument::parse(const std::string& text, const std::string& name,
                                   const std::vector<std::string>& overrides, Diagnostics& diagnostics) {
    auto data = read(text, name, std::filesystem::path(name).parent_path(), from_command_line(overrides), diagnostics);
    return SceneDocument(std::make_unique<Impl>(Impl{std::move(data)}));
}

std::vector<std::filesystem::path> SceneDocument::plugin_paths(Diagnostics& diagnostics) const {
    std::vector<std::filesystem::path> paths;
    if (!impl_->data.root) return paths;
    reporting_failures(impl_->data.sources.file(), diagnostics, [&] {
        paths = detail::read_plugin_paths(*impl_->data.root, impl_->data.sources, impl_->data.folder, diagnostics);
    });
    return paths;
}

// A document that could not be read has had its error reported by load() or parse() already.
Scene SceneDocument::validate(const Registry& registry, Diagnostics& diagnostics) const {
    Scene scene;
    scene.file = impl_->data.sources.file();
    if (!impl_->data.root) return scene;
    reporting_failures(impl_->data.sources.file(), diagnostics, [&] {
        scene =
            detail::validate_scene(*impl_->data.root, impl_->data.sources, impl_->data.folder, registry, diagnostics);
    });
    return scene;
}

}  // namespace frictionlab
