#include "frictionlab/campaign/case_outputs.hpp"

#include <string>

namespace frictionlab {

std::optional<RuptureFiles> rupture_files(const Scene& scene) {
    for (const auto& o : scene.observers) {
        if (o.type != "precursors") continue;
        const auto file = [&](const char* key) {
            const auto it = o.values.find(key);
            return scene.output_directory / (it == o.values.end() ? std::string() : std::get<std::string>(it->second));
        };
        return RuptureFiles{file("events_file"), file("summary_file")};
    }
    return std::nullopt;
}

}  // namespace frictionlab
