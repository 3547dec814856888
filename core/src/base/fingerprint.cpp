#include "frictionlab/base/fingerprint.hpp"

#include <cstdint>
#include <fstream>

#include <fmt/format.h>

namespace frictionlab {

std::string fnv1a_hex(std::string_view bytes) {
    std::uint64_t hash = 14695981039346656037ull;
    for (const unsigned char c : bytes) {
        hash ^= c;
        hash *= 1099511628211ull;
    }
    return fmt::format("{:016x}", hash);
}

std::string file_fingerprint(const std::filesystem::path& file) {
    std::error_code ec;
    const auto size = std::filesystem::file_size(file, ec);
    std::ifstream in(file, std::ios::binary);
    if (ec || !in) return "unreadable";
    std::string bytes(size, '\0');
    in.read(bytes.data(), static_cast<std::streamsize>(size));
    return in ? fnv1a_hex(bytes) : "unreadable";
}

}  // namespace frictionlab
