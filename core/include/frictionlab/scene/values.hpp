#pragma once
// Typed values from scene nodes, checked against a ParamInfo: the one place where YAML text becomes
// a ParamValue, for plugin parameters and the scene's own keys alike, and back again.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "frictionlab/base/param_spec.hpp"
#include "frictionlab/scene/yaml.hpp"

namespace frictionlab::detail {

/// A key of a mapping and its value. The key locates an empty value, whose own mark is useless.
struct Entry {
    YAML::Node key, value;
    const YAML::Node& site() const { return value.IsNull() && key.IsDefined() ? key : value; }
};

/// The value of `info`'s key, or nullopt after reporting why it is not acceptable.
std::optional<ParamValue> read_value(const ParamInfo& info, const Entry& entry, const std::string& path,
                                     const Reporter& reporter);

/// The keys one mapping of the scene may hold.
struct SectionKeys {
    std::string what;                     // names the mapping in messages: "a stage", "the scene"
    std::vector<ParamInfo> params;        // keys read as typed values
    std::vector<std::string> other_keys;  // keys the caller reads itself
    bool report_unknown = true;           // false when the keys are unknowable (unknown type)
};

/// One mapping read against its keys.
struct Section {
    ParamValues values;                               // typed keys given with a valid value
    std::map<std::string, Entry, std::less<>> given;  // every known key given (first occurrence)
    bool valid = true;  // a mapping, every given key known and valid, every required key present
};

Section read_section(const Entry& map, const std::string& path, const SectionKeys& keys, const Reporter& reporter);

/// "a number in s", "an integer", "true or false", ...: what a key takes, for messages.
std::string expectation(const ParamInfo& info);

void report_missing(const YAML::Node& map, const std::string& path, const std::string& expected, const std::string& doc,
                    const Reporter& reporter);

/// Writes a value as a scene spells it, so that reading it back gives the same value.
void emit_value(YAML::Emitter& out, const ParamValue& value);
/// emit_value() as flow text, for one-line snippets.
std::string yaml_text(const ParamValue& value);

}  // namespace frictionlab::detail
