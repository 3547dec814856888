#include "frictionlab/plugins/registry.hpp"

#include <algorithm>
#include <system_error>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace frictionlab {

namespace {
std::string provider(const std::string& library) { return library.empty() ? std::string("the program") : library; }

/// Why the types a plugin just registered (types[first..]) cannot join those before them, or "".
std::string duplicate_in(const std::vector<TypeInfo>& types, std::size_t first) {
    for (std::size_t j = first; j < types.size(); ++j)
        for (std::size_t i = 0; i < j; ++i)
            if (types[i].kind == types[j].kind && types[i].type == types[j].type)
                return i >= first
                           ? fmt::format("it registers {} type '{}' twice", to_string(types[j].kind), types[j].type)
                           : fmt::format("{} type '{}' is already provided by {}", to_string(types[j].kind),
                                         types[j].type, provider(types[i].library));
    return {};
}
}  // namespace

bool TypeInfo::works_in(int dimension) const {
    return std::find(dimensions.begin(), dimensions.end(), dimension) != dimensions.end();
}

std::string TypeInfo::dimensions_text() const {
    std::vector<std::string> names;
    for (const int d : dimensions) names.push_back(fmt::format("{}D", d));
    const std::string text = names.size() == 1 ? names.front() + " only" : fmt::format("{}", fmt::join(names, " and "));
    return dimension_limit.empty() ? text : fmt::format("{} ({})", text, dimension_limit);
}

void Registry::check_dimension(const TypeInfo& info, int dimension) {
    if (!info.works_in(dimension))
        throw InputError(fmt::format("{} type '{}' works in {}; this body is {}D", to_string(info.kind), info.type,
                                     info.dimensions_text(), dimension));
}

Registry::Registry() = default;

Registry::~Registry() {
    // Objects made from plugin code are gone by now (the registry outlives them); drop the type
    // table, whose factories are plugin code, before the handles close.
    types_.clear();
}

void Registry::add(TypeInfo info) {
    // While a plugin registers, duplicates are judged once its register function has returned (in
    // load()), so a plugin cannot catch the refusal and carry on half-registered.
    if (current_library_.empty())
        if (const TypeInfo* existing = find(info.kind, info.type))
            throw InputError(fmt::format("{} type '{}' is provided twice: by {} and by the program",
                                         to_string(info.kind), info.type, provider(existing->library)));
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
    // The same file twice is one library: dlopen would hand back the same handle, and registering
    // its types again would refuse them as duplicates of themselves.
    for (const auto& lib : libraries_)
        if (std::error_code ec; std::filesystem::equivalent(lib->record().file, file, ec)) return lib->record();

    auto library = std::make_unique<PluginLibrary>(file);
    const PluginRecord record = library->record();
    // The plugin's types are appended, then dropped again if anything is wrong with them, so a
    // refused plugin leaves the registry as it was.
    const std::size_t before = types_.size();
    const auto refuse = [&](const std::string& why) {
        types_.resize(before);
        current_library_.clear();
        return InputError(fmt::format("{}: cannot use this plugin: {}", record.file.string(), why));
    };
    current_library_ = record.file.string();
    try {
        library->header().register_types(*this);
    } catch (const std::exception& e) {
        // Formatted here: the exception object may be of a type that lives in the plugin.
        throw refuse(fmt::format("its register function failed: {}", e.what()));
    } catch (...) {
        throw refuse("its register function threw");
    }
    if (auto why = duplicate_in(types_, before); !why.empty()) throw refuse(why);
    current_library_.clear();
    libraries_.push_back(std::move(library));
    return record;
}

std::vector<SkippedPlugin> Registry::load_directory(const std::filesystem::path& dir) {
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec))
        throw InputError(fmt::format("plugin directory '{}' does not exist", dir.string()));
    std::vector<std::filesystem::path> files;
    try {
        for (const auto& entry : std::filesystem::directory_iterator(dir))
            if (entry.is_regular_file() && entry.path().extension() == ".so") files.push_back(entry.path());
    } catch (const std::filesystem::filesystem_error& e) {
        throw InputError(fmt::format("plugin directory '{}' cannot be read: {}", dir.string(), e.code().message()));
    }
    std::sort(files.begin(), files.end());  // deterministic load order
    std::vector<SkippedPlugin> skipped;
    // A plugin is named after its file; the first of a name wins, so a directory searched earlier
    // overrides the shipped plugins. A skipped file overrides nothing: the next of its name loads.
    for (const auto& f : files) {
        const auto name = f.stem().string();
        const bool loaded = std::any_of(libraries_.begin(), libraries_.end(), [&](const auto& lib) {
            const auto r = lib->record();
            return r.name == name || r.file.stem().string() == name;
        });
        const bool known_bad = std::any_of(skipped_.begin(), skipped_.end(), [&](const SkippedPlugin& s) {
            return std::filesystem::equivalent(s.file, f, ec);
        });
        if (loaded || known_bad) continue;
        try {
            load(f);
        } catch (const InputError& e) {
            // Named as in the message: absolute, whatever directory was searched.
            skipped.push_back({std::filesystem::absolute(f, ec).lexically_normal(), e.what()});
            skipped_.push_back(skipped.back());
        }
    }
    return skipped;
}

std::vector<PluginRecord> Registry::plugins() const {
    std::vector<PluginRecord> out;
    for (const auto& lib : libraries_) out.push_back(lib->record());
    return out;
}

}  // namespace frictionlab
