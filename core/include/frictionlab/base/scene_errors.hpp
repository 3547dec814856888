#pragma once
// Input errors that have a place in a scene, thrown together: every refusal found while a scene is
// assembled (a component refusing its set-up, fields no effect publishes, needs no component meets)
// reaches the user as validation errors do, each once, GCC-style, not as one log line wrapping them.
#include "frictionlab/base/diagnostics.hpp"
#include "frictionlab/base/errors.hpp"

namespace frictionlab {

/// An InputError (exit code 2) made of diagnostics; what() is Diagnostics::format() without its
/// last newline, so code that only knows InputError still shows every one of them.
class SceneErrors : public InputError {
public:
    explicit SceneErrors(Diagnostics diagnostics);
    /// One diagnostic.
    explicit SceneErrors(Diagnostic diagnostic);
    ~SceneErrors() override;
    const Diagnostics& diagnostics() const { return diagnostics_; }

private:
    Diagnostics diagnostics_;
};

}  // namespace frictionlab
