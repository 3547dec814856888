#include "frictionlab/scene/scene.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>

#include <fmt/format.h>

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
    std::error_code ec;
    const auto fail = [&](const std::string& why) {
        diagnostics.error({file.string(), 0, 0}, "", "cannot read the scene file: " + why);
        return std::nullopt;
    };
    const auto status = std::filesystem::status(file, ec);
    if (!std::filesystem::exists(status)) return fail("it does not exist");
    if (std::filesystem::is_directory(status)) return fail("it is a folder");
    // A device (/dev/zero) would be read without end, a FIFO would block until written to.
    if (!std::filesystem::is_regular_file(status)) return fail("it is not a regular file (a device, FIFO or socket)");
    const auto size = std::filesystem::file_size(file, ec);
    if (!ec && size > largest_scene_file)
        return fail(fmt::format("it is {} bytes; a scene file may have at most {} bytes", size, largest_scene_file));
    std::ifstream in(file, std::ios::binary);
    if (!in) return fail(std::strerror(errno));
    std::string text;
    text.resize(largest_scene_file + 1);
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    if (in.bad()) return fail(std::strerror(errno));
    text.resize(static_cast<std::size_t>(in.gcount()));
    if (text.size() > largest_scene_file)  // grew while being read
        return fail(fmt::format("it has more than {} bytes, the most a scene file may have", largest_scene_file));
    return text;
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
