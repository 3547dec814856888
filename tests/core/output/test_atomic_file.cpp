// Files written whole (output/atomic_file.hpp), as every output but the appended tables is: a
// reader sees the previous version or the new one, never a part, whatever durability the caller
// asks for; a failed write names the file and leaves the previous version and no temporary file.
#include <filesystem>

#include <gtest/gtest.h>

#include "cli.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/output/atomic_file.hpp"

namespace frictionlab {
namespace {

namespace fs = std::filesystem;
using testing::read_text;

constexpr Durability both[] = {Durability::atomic, Durability::durable};

bool has_temporary_file(const fs::path& dir) {
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().extension() == ".tmp") return true;
    return false;
}

TEST(AtomicFile, ReplacesTheWholeFileAndLeavesNoTemporaryFile) {
    const fs::path dir = testing::work_directory(), file = dir / "record.yaml";
    for (const Durability durability : both) {
        write_file_atomically(file, "first: 1\n", durability);
        EXPECT_EQ(read_text(file), "first: 1\n");
        write_file_atomically(file, "second: 2\n", durability);
        EXPECT_EQ(read_text(file), "second: 2\n");
        replace_file_atomically(
            file, [](const fs::path& tmp) { return fs::copy_file(tmp.parent_path() / "record.yaml", tmp); },
            durability);
        EXPECT_EQ(read_text(file), "second: 2\n");
        EXPECT_FALSE(has_temporary_file(dir));
    }
}

TEST(AtomicFile, AFailedWriteNamesTheFileAndKeepsThePreviousVersion) {
    const fs::path dir = testing::work_directory(), file = dir / "series.pvd";
    for (const Durability durability : both) {
        write_file_atomically(file, "kept\n", durability);
        try {
            replace_file_atomically(
                file,
                [](const fs::path& tmp) {
                    write_file_atomically(tmp, "half");  // a writer that fails half way
                    return false;
                },
                durability);
            ADD_FAILURE() << "a failed write was taken";
        } catch (const RunError& e) {
            EXPECT_NE(std::string(e.what()).find("cannot write '" + file.string() + "'"), std::string::npos)
                << e.what();
        }
        EXPECT_EQ(read_text(file), "kept\n");
        EXPECT_FALSE(has_temporary_file(dir));
        EXPECT_THROW(write_file_atomically(dir / "no_such_folder" / "x.yaml", "x", durability), RunError);
    }
}

}  // namespace
}  // namespace frictionlab
