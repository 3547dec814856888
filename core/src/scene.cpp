// PLACEHOLDER: being written (scene parsing and validation).
#include "frictionlab/scene.hpp"
#include "frictionlab/registry.hpp"
namespace frictionlab {
struct SceneDocument::Impl {};
SceneDocument::SceneDocument(std::unique_ptr<Impl> i) : impl_(std::move(i)) {}
SceneDocument::SceneDocument(SceneDocument&&) noexcept = default;
SceneDocument& SceneDocument::operator=(SceneDocument&&) noexcept = default;
SceneDocument::~SceneDocument() = default;
SceneDocument SceneDocument::load(const std::filesystem::path&, const std::vector<std::string>&, Diagnostics&) { throw InputError("todo"); }
SceneDocument SceneDocument::parse(const std::string&, const std::string&, const std::vector<std::string>&, Diagnostics&) { throw InputError("todo"); }
std::vector<std::filesystem::path> SceneDocument::plugin_paths(Diagnostics&) const { return {}; }
Scene SceneDocument::validate(const Registry&, Diagnostics&) const { return {}; }
std::string example_yaml(const TypeInfo&) { return {}; }
}
