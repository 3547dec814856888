// Whole scenes with the hybrid stepper against RK4 (the paper's method, dt = 2e-7 s).
#include <gtest/gtest.h>

#include "cli.hpp"
#include "csv.hpp"

namespace frictionlab {
namespace {

std::string scene(const std::string& name) { return std::string(SCENES) + "/" + name; }

}  // namespace
}  // namespace frictionlab
