#include "frictionlab/base/live_line.hpp"

#include <cstdio>

namespace frictionlab {

void show_live_line(const std::string& text) {
    std::fprintf(stderr, "\r\033[K%s", text.c_str());
    std::fflush(stderr);
}

void clear_live_line() {
    std::fputs("\r\033[K", stderr);
    std::fflush(stderr);
}

}  // namespace frictionlab
