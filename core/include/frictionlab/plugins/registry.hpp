#pragma once
// The run-owned registry of component types (share/docs/architecture.md). Plugins add their types by an
// ordinary call, registry.add<T>(), from the register function their entry point names.
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "frictionlab/model/context.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/model/kinds.hpp"
#include "frictionlab/base/param_spec.hpp"
#include "frictionlab/plugins/library.hpp"

namespace frictionlab {

/// One registered type, type-erased: its documentation and how to make it.
struct TypeInfo {
    Kind kind{};
    std::string type;     // scene `type:` name, lower_snake_case
    std::string summary;  // one paragraph: the physics and its reference
    std::vector<ParamInfo> params;
    std::vector<ParamRule> rules;
    OutputNames outputs;             // the files it writes, if it declared them (ParamSpec::writes)
    std::string library;             // the plugin file that provides it ("" for types added by code)
    bool drives_loading = false;     // loaders: loading starts with the first stage it acts in
    std::vector<int> dimensions{2};  // spatial dimensions of the bodies it works on (ParamSpec::dimensions)
    std::string dimension_limit;     // why not in others
    /// Bulk models: the dimension of the body it builds from these values.
    std::function<int(const ParamValues&)> body_dimension;
    std::function<std::unique_ptr<Component>(const ParamValues&, const Context&)> create;

    bool works_in(int dimension) const;
    /// "2D and 3D", or "2D only (<limit>)": what `frictionlab doc` shows and a refusal says.
    std::string dimensions_text() const;
};

template <class T>
constexpr Kind kind_of() {
    if constexpr (std::is_base_of_v<BulkModel, T>)
        return Kind::bulk_model;
    else if constexpr (std::is_base_of_v<FrictionLaw, T>)
        return Kind::friction_law;
    else if constexpr (std::is_base_of_v<Loader, T>)
        return Kind::loader;
    else if constexpr (std::is_base_of_v<Observer, T>)
        return Kind::observer;
    else {
        static_assert(std::is_base_of_v<Integrator, T>, "T must derive from one of the plugin kinds");
        return Kind::integrator;
    }
}

/// A plugin file of a searched directory that could not be used.
struct SkippedPlugin {
    std::filesystem::path file;
    std::string message;  // "<file>: cannot use this plugin: <reason>"
};

class Registry {
public:
    Registry();
    ~Registry();
    Registry(const Registry&) = delete;
    Registry& operator=(const Registry&) = delete;

    /// Registers T: T::type, T::spec() and a constructor T(const T::Params&, const Context&).
    template <class T>
    void add() {
        auto spec = T::spec();
        TypeInfo info;
        info.kind = kind_of<T>();
        info.type = std::string(T::type);
        info.summary = spec.summary();
        info.params = spec.params();
        info.rules = spec.erased_rules();
        info.outputs = spec.erased_outputs();
        info.drives_loading = spec.drives();
        info.dimensions = spec.spatial_dimensions();
        info.dimension_limit = spec.dimension_limit();
        info.body_dimension = spec.erased_body_dimension();
        info.create = [spec](const ParamValues& values, const Context& ctx) -> std::unique_ptr<Component> {
            return std::make_unique<T>(spec.build(values), ctx);
        };
        add(std::move(info));
    }
    /// Throws InputError if the kind already has a type of that name (naming both libraries).
    void add(TypeInfo info);

    const TypeInfo* find(Kind kind, std::string_view type) const;
    /// The types of one kind, sorted by name.
    std::vector<const TypeInfo*> types(Kind kind) const;

    /// Makes a component of kind K; the type must exist (scene validation has checked it) and work
    /// in the dimension of the context's body (idem).
    template <class K>
    std::unique_ptr<K> create(std::string_view type, const ParamValues& values, const Context& ctx) const {
        const TypeInfo* info = find(kind_of<K>(), type);
        if (!info) throw InputError("no " + std::string(to_string(kind_of<K>())) + " type '" + std::string(type) + "'");
        if (ctx.body) check_dimension(*info, ctx.body->dimension());
        return std::unique_ptr<K>(static_cast<K*>(info->create(values, ctx).release()));
    }
    /// Throws InputError if the type does not work on a body of `dimension` axes.
    static void check_dimension(const TypeInfo& info, int dimension);

    /// Loads one plugin library and registers its types. Throws InputError naming the file and the
    /// reason (unloadable, no entry symbol, ABI mismatch with the first differing field, duplicate
    /// type, register function that threw); a refused plugin leaves the registry unchanged.
    PluginRecord load(const std::filesystem::path& file);
    /// Loads every plugin (*.so) of the directory whose types are not already known. A file that
    /// cannot be used is skipped, so that one broken file does not stop commands that never need
    /// it; returns the files this call skipped, each with load()'s message (none twice). A missing
    /// or unreadable directory is an InputError.
    std::vector<SkippedPlugin> load_directory(const std::filesystem::path& dir);
    /// The libraries loaded so far, in load order.
    std::vector<PluginRecord> plugins() const;
    /// Every file load_directory() skipped so far, in order: where a missing type may have been.
    const std::vector<SkippedPlugin>& skipped() const { return skipped_; }

private:
    // Declared first so they are destroyed last: every object made from a library's code (and the
    // std::function objects in types_) must be gone before its handle is closed.
    std::vector<std::unique_ptr<PluginLibrary>> libraries_;
    std::vector<TypeInfo> types_;
    std::string current_library_;
    std::vector<SkippedPlugin> skipped_;
};

}  // namespace frictionlab
