#pragma once
// Reading a small file whole where a user may have put something else at its name: a device would be
// read without end, a FIFO would block until written to, a huge file would exhaust memory.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace frictionlab {

struct BoundedRead {
    std::optional<std::string> text;  // the whole file, if it could be read
    std::string problem;              // else why not, e.g. "it is not a regular file (a device, FIFO or socket)"
};

/// The text of `file` if it is a regular file of at most `most_bytes`. `what` names such a file in
/// the message about its size ("a scene file").
BoundedRead read_bounded_file(const std::filesystem::path& file, std::uintmax_t most_bytes, std::string_view what);

}  // namespace frictionlab
