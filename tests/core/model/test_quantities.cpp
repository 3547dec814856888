// Published quantities: a field is stored once whoever declares it first, a field read but never
// published is named with its reader, and a checkpoint gives every value back into the same storage.
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/base/state_archive.hpp"
#include "frictionlab/model/quantities.hpp"

namespace frictionlab {
namespace {

TEST(Quantities, APublishedFieldStartsAtZeroAndKeepsItsStorage) {
    Quantities q;
    Eigen::ArrayXd& force = q.field("normal_force", "interface", 3, "N", "Normal force on the block.");
    EXPECT_EQ(force.size(), 3);
    EXPECT_TRUE((force == 0).all());
    force << 1, 2, 3;
    // Declaring it again returns the same array, and the first declaration's unit and doc stand.
    EXPECT_EQ(&q.field("normal_force", "interface", 3, "kN", "other"), &force);
    for (int k = 0; k < 20; ++k) q.field(fmt::format("field_{}", k), "all", 2, "1", "");
    const Quantities::Field* f = q.find_field("normal_force");
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(&f->values, &force) << "storage never moves: effects keep references to it";
    EXPECT_EQ(f->unit, "N");
    EXPECT_EQ(f->doc, "Normal force on the block.");
    EXPECT_EQ(f->node_set, "interface");
    EXPECT_TRUE(f->published);
    EXPECT_TRUE(f->readers.empty());
    EXPECT_EQ(q.find_field("shear_force"), nullptr);
}

TEST(Quantities, AFieldNeededBeforeItIsPublishedSharesThePublishersStorage) {
    Quantities q;
    const Eigen::ArrayXd& read = q.needed_field("normal_force", "interface", 2, "friction");
    Eigen::ArrayXd& written = q.field("normal_force", "interface", 2, "N", "Normal force.");
    EXPECT_EQ(&read, &written);
    written << 4, 5;
    EXPECT_EQ(read(1), 5);
    EXPECT_EQ(q.find_field("normal_force")->unit, "N");
    EXPECT_TRUE(q.unpublished_fields().empty());
}

TEST(Quantities, AFieldNeededButNeverPublishedIsNamedWithEveryReaderAndItsRemedy) {
    Quantities q;
    q.needed_field("junctions_pinned", "interface", 4, "observers[0]", "set criterion: slip");
    q.needed_field("junctions_pinned", "interface", 4, "observers[2]");
    q.field("driving_force_field", "top", 1, "N", "");  // published, read by nobody: not listed
    const auto missing = q.unpublished_fields();
    ASSERT_EQ(missing.size(), 2u);
    for (const auto& m : missing) {
        EXPECT_EQ(m.name, "junctions_pinned");
        EXPECT_EQ(m.node_set, "interface");
    }
    EXPECT_EQ(missing[0].reader, (Quantities::Reader{"observers[0]", "set criterion: slip"}));
    EXPECT_EQ(missing[1].reader, (Quantities::Reader{"observers[2]", ""}));
}

TEST(Quantities, AFieldDeclaredOverAnotherNodeSetOrSizeIsAnInputError) {
    Quantities q;
    q.field("normal_force", "interface", 3, "N", "");
    try {
        q.needed_field("normal_force", "top", 3, "friction");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(),
                     "quantity 'normal_force' is declared twice with different node sets ('interface' and 'top')");
    }
    EXPECT_THROW(q.field("normal_force", "interface", 4, "N", ""), InputError);
}

TEST(Quantities, AScalarIsDeclaredOnceAndStartsAtZero) {
    Quantities q;
    double& drive = q.scalar("driving_force", "N", "Force of the driving spring.");
    EXPECT_EQ(drive, 0);
    drive = 2.5;
    EXPECT_EQ(&q.scalar("driving_force", "kN", "other"), &drive);
    const Quantities::Scalar* s = q.find_scalar("driving_force");
    ASSERT_NE(s, nullptr);
    EXPECT_EQ(s->value, 2.5);
    EXPECT_EQ(s->unit, "N");
    EXPECT_EQ(s->doc, "Force of the driving spring.");
    EXPECT_EQ(q.find_scalar("normal_force"), nullptr);
}

/// A run's quantities: two fields and a scalar.
struct Declared {
    Declared() {
        pinned << 1, 0, 2;
        force << 0.5, -0.25;
        drive = 7.0;
    }
    Quantities q;
    Eigen::ArrayXd& pinned = q.field("junctions_pinned", "interface", 3, "1", "");
    Eigen::ArrayXd& force = q.field("normal_force", "top", 2, "N", "");
    double& drive = q.scalar("driving_force", "N", "");
};

/// The bytes a checkpoint holds of `q`.
std::string saved(const Quantities& q) {
    std::ostringstream bytes;
    {
        StateOut out(bytes);
        q.save_state(out);
    }
    return bytes.str();
}

/// What restoring `bytes` into `q` throws; "" if they read back.
std::string restore_error(const std::string& bytes, Quantities& q) {
    std::istringstream stream(bytes);
    StateIn in(stream);
    try {
        q.restore_state(in);
    } catch (const cereal::Exception& e) {
        return e.what();
    }
    return "";
}

TEST(Quantities, ACheckpointRestoresEveryValueIntoTheSameStorage) {
    Declared before, after;
    after.pinned.setZero(), after.force.setZero(), after.drive = 0;
    const double* storage = after.pinned.data();
    EXPECT_EQ(restore_error(saved(before.q), after.q), "");
    EXPECT_EQ(after.pinned.data(), storage);
    EXPECT_TRUE((after.pinned == before.pinned).all());
    EXPECT_TRUE((after.force == before.force).all());
    EXPECT_EQ(after.drive, 7.0);
}

TEST(Quantities, ACheckpointOfOtherQuantitiesIsRefusedNamingWhat) {
    const std::string bytes = saved(Declared().q);
    Quantities fewer;
    fewer.field("junctions_pinned", "interface", 3, "1", "");
    EXPECT_EQ(restore_error(bytes, fewer), "the checkpoint has another set of published fields");
    Quantities resized;
    resized.field("junctions_pinned", "interface", 4, "1", "");
    resized.field("normal_force", "top", 2, "N", "");
    EXPECT_EQ(restore_error(bytes, resized),
              "the checkpoint's quantity 'junctions_pinned' is not one this run publishes");
    Quantities renamed;
    renamed.field("junctions_pinned", "interface", 3, "1", "");
    renamed.field("normal_force", "top", 2, "N", "");
    renamed.scalar("loading_force", "N", "");
    EXPECT_EQ(restore_error(bytes, renamed), "the checkpoint's quantity 'driving_force' is not one this run publishes");
}

}  // namespace
}  // namespace frictionlab
