#pragma once
// Builds a Simulation from a scene file exactly as `frictionlab run` does (same parser, same
// plugins from the build tree), for tests that need the assembled model rather than the CLI.
#include <memory>
#include <string>
#include <vector>

#include <spdlog/logger.h>

#include "frictionlab/plugins/registry.hpp"
#include "frictionlab/scene/scene.hpp"
#include "frictionlab/simulation/simulation.hpp"

namespace frictionlab::testing {

/// Parses and validates a scene with the build tree's plugins loaded into `registry`; a scene error
/// throws with the diagnostics.
Scene load_scene(const std::string& scene_file, const std::vector<std::string>& overrides, Registry& registry);

class SceneFixture {
public:
    explicit SceneFixture(const std::string& scene_file, const std::vector<std::string>& overrides = {});
    Simulation& sim() { return *sim_; }
    const Scene& scene() const { return scene_; }
    /// Runs every stage of the scene.
    void run_all_stages();
    /// The published field over the interface, or a test failure if absent.
    const Eigen::ArrayXd& field(const std::string& name);

private:
    spdlog::logger log_{"test"};
    Registry registry_;
    Scene scene_;
    std::unique_ptr<Simulation> sim_;
};

}  // namespace frictionlab::testing
