#pragma once
// An accuracy study: one base scene run as a converged reference and as cases that each turn
// accuracy knobs (integrator, time step or tolerance, lattice resolution, spring law, junction
// size), each case a list of `--set` overrides. The format is in share/docs/scene-format.md
// ("Accuracy studies"); `frictionlab study` runs it (study_run.hpp). Reading is two-pass like a
// scene's: the study's own keys first, then every case's scene against the registry.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "frictionlab/base/diagnostics.hpp"
#include "frictionlab/scene/scene.hpp"

namespace frictionlab {

class Registry;

struct StudyCase {
    std::string name;    // "reference" for the reference
    std::string family;  // curve of the work-precision plot; empty: the case's integrator type
    SourceLocation where;
    std::vector<SceneOverride> overrides;  // each located in the study file
};

/// One run of a study: a case with one of the study's seeds (none: the scene's own seed).
struct StudyRun {
    const StudyCase* spec;
    std::optional<std::int64_t> seed;
    /// "hybrid", or "hybrid (seed 2)" where the study has seeds.
    std::string label() const;
    /// Where it writes, below the study's output: cases/<name>, or cases/<name>/seed_<seed>.
    std::filesystem::path directory() const;
};

struct Study {
    std::filesystem::path file;
    std::string title;
    std::filesystem::path scene;  // the base scene, resolved against the study file's folder
    SourceLocation scene_where;
    double observe_every = 1.0e-6;  // s, cadence of the rupture-event detection
    double profile_every = 1.0e-4;  // s, cadence of the interface profiles
    StudyCase reference;
    std::vector<StudyCase> cases;
    std::vector<std::int64_t> seeds;  // empty: the base scene's seed only
    SourceLocation seeds_where;
    /// The reference first, then the cases in file order.
    std::vector<const StudyCase*> all_cases() const;
    /// Every case of all_cases() with each seed in turn (the reference's runs first, one per seed).
    std::vector<StudyRun> runs() const;
};

/// The study's own keys, with file:line:column errors; the base scene is not read yet.
Study read_study(const std::filesystem::path& file, Diagnostics& diagnostics);

/// The scene of each run of runs(): the base scene with the case's overrides and the run's seed,
/// checked like any scene (errors in an override point at the study file), writing into
/// `output/` its directory() and observed as the study needs (its observers replace the scene's).
std::vector<Scene> study_scenes(const Study& study, const std::filesystem::path& output, const Registry& registry,
                                Diagnostics& diagnostics);

}  // namespace frictionlab
