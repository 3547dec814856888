// libFuzzer target: any bytes as a scene file, read and validated as `frictionlab check` does
// (against the in-process test types, which cover every value type, bound, choice and rule).
// Bad input must give diagnostics, never a crash, a hang, an uncaught exception or a sanitizer
// report. Built with clang and -fsanitize=fuzzer when FRICTIONLAB_FUZZERS is on; the normal build
// replays the committed corpus through the same function (fuzz_scene_corpus).
#include <cstddef>
#include <cstdint>
#include <string>

#include "frictionlab/plugins/registry.hpp"
#include "frictionlab/scene/scene.hpp"
#include "test_scene_types.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // Built once, for every input: reachable until exit, so no leak is reported.
    static const frictionlab::Registry* registry = [] {
        auto* r = new frictionlab::Registry;
        frictionlab::testing::register_scene_test_types(*r);
        return r;
    }();
    const std::string text(reinterpret_cast<const char*>(data), size);
    frictionlab::Diagnostics diagnostics;
    const auto document = frictionlab::SceneDocument::parse(text, "fuzz.yaml", {}, diagnostics);
    document.plugin_paths(diagnostics);
    const frictionlab::Scene scene = document.validate(*registry, diagnostics);
    (void)diagnostics.format();
    return 0;
}
