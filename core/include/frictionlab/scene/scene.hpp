#pragma once
// A scene: the YAML file a user writes (format in share/docs/scene-format.md), parsed once into
// typed specs. Reading is two-pass because the plugin paths a scene names decide which types exist:
//
//     Diagnostics d;
//     auto doc = SceneDocument::load(file, overrides, d);       // YAML, duplicate keys, --set
//     for (auto& p : doc.plugin_paths(d)) registry.load_directory(p);
//     Scene scene = doc.validate(registry, d);                   // every key, type and bound
//     if (!d.empty()) { print d.format(); exit 2; }
#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "frictionlab/base/diagnostics.hpp"
#include "frictionlab/base/param_spec.hpp"

namespace frictionlab {

class Registry;

/// One component of the scene, its parameters checked against its type's ParamSpec.
struct ComponentSpec {
    std::string path;      // key path in the scene: "bulk", "friction", "loaders[1]", ...
    SourceLocation where;  // of the component's mapping
    std::string type;
    ParamValues values;  // every declared key of the type, defaults filled in
    /// Where each key given in the scene was written (a default has no entry), so that a check made
    /// after validation (the stable step, at `integrator.dt`) points at the value.
    std::map<std::string, SourceLocation> value_where;
    // Scene-level keys beside `type` (not the plugin's own parameters):
    std::vector<std::string> stages;  // loaders: the stages it acts in (empty: all)
    double every = 0;                 // observers: cadence in simulated seconds (0: unset)
    std::int64_t every_steps = 0;     // observers: cadence in steps (0: unset)
};

struct StageSpec {
    std::string name;
    SourceLocation where;
    double duration = 0;          // s, > 0
    bool friction_events = true;  // false while settling (theory.md B.18)
    /// Checked at the end of the stage: max node speed must be below this (m/s); inf = no check.
    double max_speed_at_end = std::numeric_limits<double>::infinity();
};

/// When a run writes checkpoints (share/docs/checkpoints.md); not physics: outside the scene hash.
struct CheckpointSpec {
    double every = 0;         // simulated s between checkpoints; 0: none on this clock
    double wall_every = 600;  // wall-clock s between checkpoints; 0: none on this clock
    bool given = false;       // the scene asked for them (a component that cannot is then an error)
    bool wanted() const { return every > 0 || wall_every > 0; }
};

struct Scene {
    std::filesystem::path file;
    std::string hash;  // of the resolved scene text (defaults filled in) without `output:`, hex
    std::string title;
    std::uint64_t seed = 0;
    std::filesystem::path output_directory;           // relative paths: to the working directory
    std::vector<std::filesystem::path> plugin_paths;  // relative paths: to the scene file
    ComponentSpec bulk;
    std::optional<ComponentSpec> friction;
    std::vector<ComponentSpec> loaders;
    ComponentSpec integrator;
    std::vector<StageSpec> stages;
    std::vector<ComponentSpec> observers;
    CheckpointSpec checkpoint;
    /// The scene with every default written out, as YAML: what run.yaml records.
    std::string resolved_yaml;
};

/// One `key.path=value` override (share/docs/scene-format.md) and where its first character was
/// written, so that its errors point there: the command line, or a campaign file (campaign/campaign.hpp).
struct SceneOverride {
    std::string text;
    SourceLocation origin{"<command line>", 1, 1};
};

class SceneDocument {
public:
    /// Parses the file and applies `--set key.path=value` overrides. Malformed YAML and duplicate
    /// keys are reported to `diagnostics` with file:line:column.
    static SceneDocument load(const std::filesystem::path& file, const std::vector<std::string>& overrides,
                              Diagnostics& diagnostics);
    /// The same with overrides written elsewhere than on the command line (a study file).
    static SceneDocument load_located(const std::filesystem::path& file, const std::vector<SceneOverride>& overrides,
                                      Diagnostics& diagnostics);
    /// The same from text; `name` stands for the file in messages.
    static SceneDocument parse(const std::string& text, const std::string& name,
                               const std::vector<std::string>& overrides, Diagnostics& diagnostics);

    SceneDocument(SceneDocument&&) noexcept;
    SceneDocument& operator=(SceneDocument&&) noexcept;
    ~SceneDocument();

    /// `plugin_paths:` resolved against the scene's folder; a path that does not exist is an error.
    std::vector<std::filesystem::path> plugin_paths(Diagnostics& diagnostics) const;
    /// Every check: known keys (with "did you mean"), types, required keys, bounds, choices,
    /// known `type`s (listing the available ones), cross-key rules, stage names.
    Scene validate(const Registry& registry, Diagnostics& diagnostics) const;

private:
    struct Impl;
    explicit SceneDocument(std::unique_ptr<Impl>);
    std::unique_ptr<Impl> impl_;
};

/// A YAML snippet with every parameter of a type at its default, each key with its doc and unit as
/// a comment: what `frictionlab example KIND/TYPE` prints. It parses as a valid component.
std::string example_yaml(const struct TypeInfo& info);

}  // namespace frictionlab
