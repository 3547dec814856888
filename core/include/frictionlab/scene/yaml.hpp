#pragma once
// Reading scene YAML while keeping track of where every node came from: a line of the file, or a
// `--set` override on the command line. yaml-cpp keeps marks on nodes but silently accepts duplicate
// keys, so the reader also replays the event stream to catch them.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "frictionlab/base/diagnostics.hpp"

namespace frictionlab::detail {

/// Where each node of a scene came from. Nodes from the file carry yaml-cpp marks; nodes grafted
/// in by overrides are recorded here by identity, because their marks are relative to the override.
class SourceMap {
public:
    explicit SourceMap(std::string file) : file_(std::move(file)) {}
    const std::string& file() const { return file_; }
    void add(const YAML::Node& node, SourceLocation where);
    SourceLocation at(const YAML::Node& node) const;

private:
    std::string file_;
    std::vector<std::pair<YAML::Node, SourceLocation>> grafted_;
};

/// Diagnostics that know where nodes are.
class Reporter {
public:
    Reporter(const SourceMap& sources, Diagnostics& diagnostics) : sources_(&sources), diagnostics_(&diagnostics) {}
    void error(const YAML::Node& at, const std::string& path, std::string message) const;
    void error(SourceLocation where, const std::string& path, std::string message) const;
    SourceLocation where(const YAML::Node& node) const { return sources_->at(node); }

private:
    const SourceMap* sources_;
    Diagnostics* diagnostics_;
};

/// The first document of `text`. Malformed YAML is one error at the parser's mark (nullopt);
/// duplicate keys and extra documents are reported but the document is still returned.
std::optional<YAML::Node> read_yaml(const std::string& text, const std::string& name, Diagnostics& diagnostics);

/// 1-based location of a yaml-cpp mark (0-based; -1 when yaml-cpp has none).
SourceLocation location(const std::string& file, const YAML::Mark& mark);

/// Key paths as messages show them ("loaders[1].stiffness"); keys are escaped like quote() text.
std::string join_path(const std::string& parent, const std::string& key);
std::string index_path(const std::string& parent, std::size_t index);

/// `text` with control characters escaped and long texts cut, safe for a one-line message.
std::string escaped(const std::string& text);
/// escaped() in single quotes.
std::string quote(const std::string& text);
/// "'a', 'b', 'c'"
std::string quote_list(const std::vector<std::string>& items);
/// What a node is, for "expected X, got Y" messages: "'abc'", "a list", "a mapping", ...
std::string describe(const YAML::Node& node);
/// True for a scalar written in quotes (or as a block literal): YAML makes it a string.
bool is_quoted(const YAML::Node& node);

}  // namespace frictionlab::detail
