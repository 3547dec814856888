#include "frictionlab/registry.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace frictionlab {

Registry::Registry() = default;

Registry::~Registry() {
    // Objects made from plugin code are gone by now (the registry outlives them); drop the type
    // table, whose factories are plugin code, before the handles close.
    types_.clear();
}

void Registry::add(TypeInfo info) {
    if (const TypeInfo* existing = find(info.kind, info.type)) {
        const auto where = [](const std::string& lib) { return lib.empty() ? std::string("the program") : lib; };
        throw InputError(fmt::format("{} type '{}' is provided twice: by {} and by {}", to_string(info.kind),
                                     info.type, where(existing->library), where(current_library_)));
    }
    info.library = current_library_;
    types_.push_back(std::move(info));
}

const TypeInfo* Registry::find(Kind kind, std::string_view type) const {
    for (const auto& t : types_)
        if (t.kind == kind && t.type == type) return &t;
    return nullptr;
}

std::vector<const TypeInfo*> Registry::types(Kind kind) const {
    std::vector<const TypeInfo*> out;
    for (const auto& t : types_)
        if (t.kind == kind) out.push_back(&t);
    std::sort(out.begin(), out.end(), [](auto* a, auto* b) { return a->type < b->type; });
    return out;
}

PluginRecord Registry::load(const std::filesystem::path& file) {
    auto library = std::make_unique<PluginLibrary>(file);
    // Register into a scratch list first, so a refused plugin leaves the registry unchanged.
    const std::size_t before = types_.size();
    current_library_ = file.string();
    try {
        library->header().register_types(*this);
    } catch (const std::exception& e) {
        types_.resize(before);
        current_library_.clear();
        throw InputError(fmt::format("{}: cannot use this plugin: its register function failed: {}",
                                     file.string(), e.what()));
    } catch (...) {
        types_.resize(before);
        current_library_.clear();
        throw InputError(fmt::format("{}: cannot use this plugin: its register function threw", file.string()));
    }
    current_library_.clear();
    libraries_.push_back(std::move(library));
    return libraries_.back()->record();
}

void Registry::load_directory(const std::filesystem::path& dir) {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        if (entry.is_regular_file() && entry.path().extension() == ".so") files.push_back(entry.path());
    std::sort(files.begin(), files.end());  // deterministic load order
    for (const auto& f : files) {
        const bool loaded = std::any_of(libraries_.begin(), libraries_.end(), [&](const auto& lib) {
            return lib->record().name == f.stem().string();
        });
        if (!loaded) load(f);
    }
}

std::vector<PluginRecord> Registry::plugins() const {
    std::vector<PluginRecord> out;
    for (const auto& lib : libraries_) out.push_back(lib->record());
    return out;
}

}  // namespace frictionlab
