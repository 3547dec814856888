#include "frictionlab/simulation/loading_start.hpp"

#include <gtest/gtest.h>

namespace frictionlab {
namespace {

/// A registry with one loader type that drives the slider and one that does not.
class LoadingStart : public ::testing::Test {
protected:
    LoadingStart() {
        for (const auto& [type, drives] : {std::pair{"spring", true}, std::pair{"press", false}}) {
            TypeInfo info;
            info.kind = Kind::loader;
            info.type = type;
            info.drives_loading = drives;
            registry_.add(std::move(info));
        }
        for (const char* name : {"settle", "load", "hold"}) scene_.stages.push_back({name, {}, 0.25});
        scene_.stages[1].duration = 0.5;
    }

    ComponentSpec loader(const std::string& type, std::vector<std::string> stages = {}) {
        ComponentSpec c;
        c.type = type;
        c.stages = std::move(stages);
        return c;
    }

    Registry registry_;
    Scene scene_;
};

TEST_F(LoadingStart, IsTheStartOfTheFirstStageADrivingLoaderActsIn) {
    scene_.loaders = {loader("press"), loader("spring", {"load", "hold"})};
    EXPECT_EQ(loading_start(scene_, registry_), 0.25);
    scene_.loaders = {loader("spring", {"hold"})};
    EXPECT_EQ(loading_start(scene_, registry_), 0.75);
}

TEST_F(LoadingStart, IsZeroWhenADrivingLoaderActsInEveryStage) {
    scene_.loaders = {loader("spring")};
    EXPECT_EQ(loading_start(scene_, registry_), 0);
}

TEST_F(LoadingStart, IsTheStartOfTheLastStageWithoutADrivingLoader) {
    scene_.loaders = {loader("press", {"settle"})};
    EXPECT_EQ(loading_start(scene_, registry_), 0.75);
    scene_.loaders = {loader("unknown_type", {"load"})};
    EXPECT_EQ(loading_start(scene_, registry_), 0.75);
}

TEST_F(LoadingStart, IsZeroWithoutStages) {
    scene_.stages.clear();
    scene_.loaders = {loader("spring")};
    EXPECT_EQ(loading_start(scene_, registry_), 0);
}

}  // namespace
}  // namespace frictionlab
