#include "frictionlab/base/bounded_file.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>

#include <fmt/format.h>

namespace frictionlab {

BoundedRead read_bounded_file(const std::filesystem::path& file, std::uintmax_t most_bytes, std::string_view what) {
    std::error_code ec;
    const auto fail = [](std::string why) { return BoundedRead{std::nullopt, std::move(why)}; };
    const auto status = std::filesystem::status(file, ec);
    if (!std::filesystem::exists(status)) return fail("it does not exist");
    if (std::filesystem::is_directory(status)) return fail("it is a folder");
    if (!std::filesystem::is_regular_file(status)) return fail("it is not a regular file (a device, FIFO or socket)");
    const auto size = std::filesystem::file_size(file, ec);
    if (!ec && size > most_bytes)
        return fail(fmt::format("it is {} bytes; {} may have at most {} bytes", size, what, most_bytes));
    std::ifstream in(file, std::ios::binary);
    if (!in) return fail(std::strerror(errno));
    std::string text;
    text.resize(most_bytes + 1);
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    if (in.bad()) return fail(std::strerror(errno));
    text.resize(static_cast<std::size_t>(in.gcount()));
    if (text.size() > most_bytes)  // grew while being read
        return fail(fmt::format("it has more than {} bytes, the most {} may have", most_bytes, what));
    return {std::move(text), {}};
}

}  // namespace frictionlab
