#pragma once
// Scene errors, collected so that every error of a scene is reported in one pass, GCC-style:
//     scene.yaml:12:5: error: friction.mu_s: must be > 0, got -0.7
#include <string>
#include <vector>

namespace frictionlab {

struct SourceLocation {
    std::string file;
    int line = 0, column = 0;  // 1-based; 0 = unknown
};

struct Diagnostic {
    SourceLocation where;
    std::string key_path;  // e.g. "loaders[1].stiffness"; empty for whole-file errors
    std::string message;
    /// "file:line:column: error: key.path: message" (or another severity, e.g. "warning").
    std::string format(const std::string& severity = "error") const;
};

class Diagnostics {
public:
    void error(SourceLocation where, std::string key_path, std::string message);
    bool empty() const { return list_.empty(); }
    const std::vector<Diagnostic>& list() const { return list_; }
    /// Every diagnostic, one per line, in source order.
    std::string format() const;

private:
    std::vector<Diagnostic> list_;
};

/// The closest candidate by edit distance, if close enough to be a plausible typo ("" otherwise).
std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace frictionlab
