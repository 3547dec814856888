// The vtk_series observer, read back by VTK's own readers: in C++ (vtkXMLUnstructuredGridReader per
// .vtu, vtkXMLDataParser for the .pvd) and in Python (read_series.py, with Debian's python3-vtk9).
// The test is the single source of what was set: it writes expected.json beside each series for the
// Python reader.
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <spdlog/logger.h>
#include <vtkPoints.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "cli.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "frictionlab/simulation/system.hpp"
#include "vtk_series.hpp"

namespace frictionlab {
namespace {

namespace fs = std::filesystem;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr Index nx = 5, nz = 3;

/// A 5x3 lattice, node index ix + nx * iz, with the standard node sets (glossary). Masses are 2 kg
/// so that force -> acceleration -> force in System::refresh() is exact.
Body lattice(bool with_quads) {
    Body b;
    const double l = 0.1;
    b.reference_position.resize(nx * nz, 2);
    b.mass = Eigen::ArrayXd::Constant(nx * nz, 2.0);
    b.length = (nx - 1) * l, b.height = (nz - 1) * l, b.width = 0.01, b.spacing = l;
    for (Index iz = 0; iz < nz; ++iz)
        for (Index ix = 0; ix < nx; ++ix) {
            const Index n = ix + nx * iz;
            b.reference_position(n, 0) = ix * l, b.reference_position(n, 1) = iz * l;
            b.node_sets["all"].push_back(n);
            if (iz == 0) b.node_sets["interface"].push_back(n);
            if (iz == nz - 1) b.node_sets["top"].push_back(n);
            if (ix == 0) b.node_sets["trailing_edge"].push_back(n);
            if (ix == nx - 1) b.node_sets["leading_edge"].push_back(n);
            if (ix + 1 < nx) b.bonds.push_back({n, n + 1});
            if (iz + 1 < nz) b.bonds.push_back({n, n + nx});
            if (with_quads && ix + 1 < nx && iz + 1 < nz) b.cells.push_back({n, n + 1, n + 1 + nx, n + nx});
        }
    return b;
}

/// Pulls every node back to its reference x with stiffness k and pushes down with a weight w; like a
/// contact law it publishes a normal force on the interface and a scalar.
class TestEffect final : public Effect {
public:
    static constexpr double k = 8, w = 0.5;
    TestEffect(const Body& body, Quantities& q)
        : x0_(body.x0()),
          normal_(q.field("normal_force", "interface", nx, "N", "test contact force")),
          driving_(q.scalar("driving_force", "N", "test scalar")) {}
    std::string describe() const override { return "test effect"; }
    void add_forces(const StageView& s, ForceView& f) override {
        f.fx -= k * (s.x - x0_);
        f.fz -= w;
        for (Index i = 0; i < nx; ++i) normal_(i) = 10.0 * (i + 1) + s.t;
        driving_ = 1.5 + s.t;
    }
    /// The same virial in every cell: (V, 2 V, -V), V = 1 + t (N m).
    void add_cell_virial(const StageView& s, Eigen::Ref<Eigen::ArrayX3d> virial) const override {
        virial.col(0) += 1 + s.t, virial.col(1) += 2 * (1 + s.t), virial.col(2) -= 1 + s.t;
    }

private:
    Eigen::ArrayXd x0_;
    Eigen::ArrayXd& normal_;
    double& driving_;
};

/// What one snapshot must hold: the values the test set, worked out independently of the observer.
struct Expected {
    std::string file;
    double time = 0;
    long long step = 0;
    std::vector<double> points;
    std::map<std::string, std::pair<int, std::vector<double>>> arrays;  // name -> components, values
    std::map<std::string, double> numbers;                              // field data, one value each
    std::map<std::string, double> cell_values;  // quads: strain and stress, the same in every cell
};

std::string json_number(double v) { return std::isnan(v) ? "NaN" : fmt::format("{}", v); }

std::string json_numbers(const std::vector<double>& v) {
    std::string s = "[";
    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + json_number(v[i]);
    return s + "]";
}

std::string json_strings(const std::vector<std::string>& v) {
    std::string s = "[";
    for (std::size_t i = 0; i < v.size(); ++i) s += fmt::format("{}\"{}\"", i ? ", " : "", v[i]);
    return s + "]";
}

class VtkSeriesTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::path(FRICTIONLAB_BINARY_DIR) / "tests" / "observer_vtk_series" / test->name();
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        info_.framework_version = "9.8.7-test";
        info_.scene_file = "scene.yaml";
        info_.scene_hash = "0123456789abcdef";
        info_.seed = 18446744073709551557ull;  // beyond a double's exact integers
        info_.plugins = {{"observer_vtk_series", "0.1.0", "observer_vtk_series.so", ""},
                         {"friction_test", "1.2", "friction_test.so", ""}};
    }

    void make_system(bool with_quads = true) {
        body_ = lattice(with_quads);
        system_ = std::make_unique<System>(body_, 0);
        system_->add_effect(std::make_unique<TestEffect>(body_, quantities_));
        system_->begin_stage(stage_);
    }

    void publish_junctions() {
        for (const char* name : {"junctions_pinned", "junctions_sliding", "junctions_dislocated"})
            counts_.push_back(&quantities_.field(name, "interface", nx, "1", "test junction count"));
    }

    RunView view() {
        return RunView{*system_, body_, system_->state(), quantities_, stage_, system_->step_index(), dir_,
                       info_,    log_};
    }

    /// Moves the system to snapshot k (a different time, displacement, velocity and junction counts
    /// each), observes it, and records what the files must then hold.
    void observe(VtkSeries& observer, int k) {
        const StateLayout& l = system_->layout();
        Eigen::VectorXd y = system_->y();
        for (Index i = 0; i < body_.size(); ++i) {
            y(l.position_index(i, 0)) = body_.x0()(i) + 1e-3 * (k + 1) * (i + 1);
            y(l.position_index(i, 1)) = body_.z0()(i) - 2e-4 * k * i;
            y(l.velocity_index(i, 0)) = 0.5 * k - 0.01 * i;
            y(l.velocity_index(i, 1)) = -0.25 * i;
        }
        const double t = 0.25 * k;
        if (k == 0)
            system_->initial_state() = y;
        else
            system_->accept(t, y);
        // Junction counts per interface block; blocks 1 and 4 have none, so no pinned fraction.
        const double pinned[] = {3, 0, 1, 2, 0}, sliding[] = {1, 0, 1, 0, 0}, dislocated[] = {0, 0, 2, 2, 0};
        if (!counts_.empty())
            for (Index i = 0; i < nx; ++i) {
                const bool has_junctions = pinned[i] + sliding[i] + dislocated[i] > 0;
                (*counts_[0])(i) = pinned[i] + (has_junctions ? k : 0);
                (*counts_[1])(i) = sliding[i];
                (*counts_[2])(i) = dislocated[i];
            }
        system_->refresh();
        observer.observe(view());
        expected_.push_back(expect(k, t, y));
    }

    Expected expect(int k, double t, const Eigen::VectorXd& y) const {
        const Index n = body_.size();
        const StageView s = view_of(y, system_->layout(), t);
        Expected e;
        e.file = fmt::format("lattice/lattice_{:06d}.vtu", k);
        e.time = t;
        e.step = system_->step_index();
        auto& displacement = e.arrays["displacement"] = {3, {}};
        auto& velocity = e.arrays["velocity"] = {3, {}};
        auto& force = e.arrays["net_force"] = {3, {}};
        auto& role = e.arrays["role"] = {1, {}};
        auto& normal = e.arrays["normal_force"] = {1, {}};
        for (Index i = 0; i < n; ++i) {
            const double u = s.x(i) - body_.x0()(i);
            e.points.insert(e.points.end(), {body_.x0()(i), body_.z0()(i), 0});  // reference positions
            displacement.second.insert(displacement.second.end(), {u, s.z(i) - body_.z0()(i), 0});
            velocity.second.insert(velocity.second.end(), {s.vx(i), s.vz(i), 0});
            force.second.insert(force.second.end(), {-TestEffect::k * u, -TestEffect::w, 0});
            const Index ix = i % nx, iz = i / nx;
            role.second.push_back((iz == nz - 1 ? 1 : 0) | (iz == 0 ? 2 : 0) | (ix == 0 ? 4 : 0) |
                                  (ix == nx - 1 ? 8 : 0));
            normal.second.push_back(iz == 0 ? 10.0 * (ix + 1) + t : nan);
        }
        if (!counts_.empty()) {
            const char* names[] = {"junctions_pinned", "junctions_sliding", "junctions_dislocated"};
            for (int c = 0; c < 3; ++c) {
                auto& a = e.arrays[names[c]] = {1, std::vector<double>(n, nan)};
                for (Index i = 0; i < nx; ++i) a.second[i] = (*counts_[c])(i);
            }
            auto& fraction = e.arrays["pinned_fraction"] = {1, std::vector<double>(n, nan)};
            const double fractions[] = {(3.0 + k) / (4 + k), nan, (1.0 + k) / (4 + k), (2.0 + k) / (4 + k), nan};
            std::copy(std::begin(fractions), std::end(fractions), fraction.second.begin());
        }
        // u = a (ix + nx iz + 1), w = -b (ix + nx iz) with x = ix l, z = iz l: an affine field, so
        // every cell has its exact gradient.
        const double a = 1e-3 * (k + 1), b = 2e-4 * k, l = body_.spacing;
        // The test effect's virial (V, 2 V, -V) over the cell's volume l^2 B.
        const double stress = (1 + t) / (l * l * body_.width);
        e.cell_values = {{"strain_xx", a / l},  {"strain_zz", -b * nx / l}, {"strain_xz", 0.5 * (a * nx / l - b / l)},
                         {"stress_xx", stress}, {"stress_zz", 2 * stress},  {"stress_xz", -stress}};
        e.numbers = {{"TIME", t},
                     {"TimeValue", t},
                     {"STEP", double(e.step)},
                     {"stage_index", stage_.index},
                     {"driving_force", 1.5 + t}};
        return e;
    }

    /// expected.json beside the series, for read_series.py.
    void write_expectation(const fs::path& series_dir, int cell_type, vtkIdType cells) const {
        std::ofstream out(series_dir / "expected.json");
        const std::string plugins = "observer_vtk_series 0.1.0, friction_test 1.2";
        out << fmt::format("{{\"collection\": \"lattice.pvd\", \"points\": {}, \"cells\": {}, \"cell_type\": {},\n",
                           body_.size(), cells, cell_type);
        out << fmt::format(
            "\"strings\": {{\"framework\": [\"frictionlab\"], \"version\": {}, \"scene_hash\": {}, \"seed\": {}, "
            "\"plugins\": {}, "
            "\"stage\": {}}},\n",
            json_strings({info_.framework_version}), json_strings({info_.scene_hash}),
            json_strings({std::to_string(info_.seed)}), json_strings({plugins}), json_strings({stage_.name}));
        out << "\"snapshots\": [\n";
        for (std::size_t s = 0; s < expected_.size(); ++s) {
            const Expected& e = expected_[s];
            out << fmt::format("{{\"file\": \"{}\", \"time\": {}, \"points\": {},\n \"arrays\": {{", e.file,
                               json_number(e.time), json_numbers(e.points));
            bool first = true;
            for (const auto& [name, a] : e.arrays) {
                out << fmt::format("{}\"{}\": {{\"components\": {}, \"values\": {}}}", first ? "" : ",\n  ", name,
                                   a.first, json_numbers(a.second));
                first = false;
            }
            out << "},\n \"numbers\": {";
            first = true;
            for (const auto& [name, v] : e.numbers) {
                out << fmt::format("{}\"{}\": {}", first ? "" : ", ", name, json_number(v));
                first = false;
            }
            out << "}}" << (s + 1 < expected_.size() ? ",\n" : "\n");
        }
        out << "]}\n";
    }

    fs::path dir_;
    RunInfo info_;
    StageInfo stage_{"load", 1, 0.0, 1.0, true};
    spdlog::logger log_{"test"};
    Body body_;
    Quantities quantities_;
    std::unique_ptr<System> system_;
    std::vector<Eigen::ArrayXd*> counts_;
    std::vector<Expected> expected_;
};

VtkSeries make_observer(VtkSeries::Cells cells = VtkSeries::Cells::quads, bool compress = true,
                        spdlog::logger* log = nullptr) {
    static spdlog::logger quiet("test");
    return VtkSeries({"lattice", cells, compress},
                     Context{log ? *log : quiet, 0, nullptr, nullptr, nullptr, "observer"});
}

struct CollectionEntry {
    double time;
    std::string file;
};

/// The .pvd, parsed by VTK's XML parser (a half-written file would not parse).
std::vector<CollectionEntry> read_collection(const fs::path& pvd) {
    vtkNew<vtkXMLDataParser> parser;
    parser->SetFileName(pvd.c_str());
    EXPECT_EQ(parser->Parse(), 1) << pvd;
    vtkXMLDataElement* root = parser->GetRootElement();
    EXPECT_NE(root, nullptr);
    if (!root) return {};
    EXPECT_STREQ(root->GetAttribute("type"), "Collection");
    vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
    EXPECT_NE(collection, nullptr);
    std::vector<CollectionEntry> entries;
    for (int i = 0; collection && i < collection->GetNumberOfNestedElements(); ++i) {
        vtkXMLDataElement* d = collection->GetNestedElement(i);
        entries.push_back({std::strtod(d->GetAttribute("timestep"), nullptr), d->GetAttribute("file")});
    }
    return entries;
}

void expect_values(const std::string& what, const std::vector<double>& expected, vtkDataArray* actual) {
    ASSERT_EQ(actual->GetNumberOfValues(), static_cast<vtkIdType>(expected.size())) << what;
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const double v = actual->GetComponent(static_cast<vtkIdType>(i) / actual->GetNumberOfComponents(),
                                              static_cast<int>(i % actual->GetNumberOfComponents()));
        if (std::isnan(expected[i]))
            EXPECT_TRUE(std::isnan(v)) << what << "[" << i << "] = " << v << ", expected NaN";
        else
            EXPECT_DOUBLE_EQ(v, expected[i]) << what << "[" << i << "]";
    }
}

std::string field_string(vtkUnstructuredGrid* grid, const char* name, vtkIdType i = 0) {
    auto* a = vtkStringArray::SafeDownCast(grid->GetFieldData()->GetAbstractArray(name));
    EXPECT_NE(a, nullptr) << name;
    return a && i < a->GetNumberOfValues() ? a->GetValue(i) : std::string();
}

/// The range a .vtu header states for a field-data array (readers show it before loading the data).
double header_range_max(const fs::path& file, const char* name) {
    vtkNew<vtkXMLDataParser> parser;
    parser->SetFileName(file.c_str());
    EXPECT_EQ(parser->Parse(), 1) << file;
    vtkXMLDataElement* grid = parser->GetRootElement()->FindNestedElementWithName("UnstructuredGrid");
    vtkXMLDataElement* array =
        grid->FindNestedElementWithName("FieldData")->FindNestedElementWithNameAndAttribute("DataArray", "Name", name);
    double range_max = nan;
    if (array) array->GetScalarAttribute("RangeMax", range_max);
    return range_max;
}

/// One .vtu, read by VTK's C++ reader, against what the test set.
void expect_snapshot(const fs::path& file, const Expected& e, vtkIdType cells, int cell_type, const RunInfo& info) {
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(file.c_str());
    reader->Update();
    vtkUnstructuredGrid* grid = reader->GetOutput();
    ASSERT_EQ(grid->GetNumberOfPoints(), static_cast<vtkIdType>(e.points.size() / 3)) << file;
    ASSERT_EQ(grid->GetNumberOfCells(), cells);
    for (vtkIdType c = 0; c < cells; ++c) EXPECT_EQ(grid->GetCellType(c), cell_type);
    expect_values("points", e.points, grid->GetPoints()->GetData());
    vtkPointData* pd = grid->GetPointData();
    EXPECT_EQ(pd->GetNumberOfArrays(), static_cast<int>(e.arrays.size())) << "no array missing, none unexpected";
    for (const auto& [name, a] : e.arrays) {
        vtkDataArray* array = pd->GetArray(name.c_str());
        ASSERT_NE(array, nullptr) << name;
        EXPECT_EQ(array->GetNumberOfComponents(), a.first) << name;
        expect_values(name, a.second, array);
    }
    for (const auto& [name, v] : e.numbers) {
        vtkDataArray* array = grid->GetFieldData()->GetArray(name.c_str());
        ASSERT_NE(array, nullptr) << name;
        EXPECT_DOUBLE_EQ(array->GetComponent(0, 0), v) << name;
    }
    if (cell_type == VTK_QUAD) {
        for (const auto& [name, value] : e.cell_values) {
            vtkDataArray* array = grid->GetCellData()->GetArray(name.c_str());
            ASSERT_NE(array, nullptr) << name;
            for (vtkIdType c = 0; c < cells; ++c)
                EXPECT_NEAR(array->GetComponent(c, 0), value, 1e-12 * std::max(1.0, std::abs(value)))
                    << name << " cell " << c;
        }
    } else {
        EXPECT_EQ(grid->GetCellData()->GetNumberOfArrays(), 0) << "strain and stress only for quads";
    }
    EXPECT_DOUBLE_EQ(header_range_max(file, "TIME"), e.time) << "the header's range is this snapshot's";
    EXPECT_EQ(field_string(grid, "framework"), "frictionlab");
    EXPECT_EQ(field_string(grid, "version"), info.framework_version);
    EXPECT_EQ(field_string(grid, "scene_file"), "scene.yaml") << "the file name, as every output records it";
    EXPECT_EQ(field_string(grid, "scene_hash"), info.scene_hash);
    EXPECT_EQ(field_string(grid, "seed"), std::to_string(info.seed));
    EXPECT_EQ(field_string(grid, "plugins"), "observer_vtk_series 0.1.0, friction_test 1.2");
    EXPECT_EQ(field_string(grid, "stage"), "load");
}

void expect_series(const fs::path& dir, const std::vector<Expected>& expected, vtkIdType cells, int cell_type,
                   const RunInfo& info) {
    const auto entries = read_collection(dir / "lattice.pvd");
    ASSERT_EQ(entries.size(), expected.size());
    for (std::size_t s = 0; s < expected.size(); ++s) {
        EXPECT_EQ(entries[s].file, expected[s].file);
        EXPECT_EQ(entries[s].time, expected[s].time) << "the .pvd time is the simulated time, exactly";
        expect_snapshot(dir / entries[s].file, expected[s], cells, cell_type, info);
    }
}

std::vector<fs::path> temporary_files(const fs::path& dir) {
    std::vector<fs::path> found;
    for (const auto& f : fs::recursive_directory_iterator(dir))
        if (f.path().extension() == ".tmp") found.push_back(f.path());
    return found;
}

/// read_series.py with a Python that has VTK (Debian: python3-vtk9); its exit code is the verdict.
void expect_python_reads(const fs::path& dir) {
    if (std::string(FRICTIONLAB_VTK_PYTHON).empty()) GTEST_SKIP() << "no Python with VTK's bindings configured";
    const std::string command =
        fmt::format("\"{}\" \"{}\" \"{}\"", FRICTIONLAB_VTK_PYTHON, READ_SERIES_SCRIPT, dir.string());
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
}

TEST_F(VtkSeriesTest, WritesASeriesThatVtkReadsBackInCppAndPython) {
    make_system();
    publish_junctions();
    VtkSeries observer = make_observer();
    observer.begin(view());
    for (int k = 0; k < 3; ++k) observe(observer, k);
    observer.end(view());

    expect_series(dir_, expected_, 8, VTK_QUAD, info_);
    EXPECT_TRUE(temporary_files(dir_).empty()) << "a normal end leaves no temporary file";
    write_expectation(dir_, VTK_QUAD, 8);
    expect_python_reads(dir_);
}

TEST_F(VtkSeriesTest, AnInterruptedSeriesStillOpens) {
    make_system();
    publish_junctions();
    VtkSeries observer = make_observer();
    observer.begin(view());
    observe(observer, 0);
    observe(observer, 1);
    // As if the process were killed now: no end(), the files as they are on disk.
    const fs::path copy = dir_.string() + "_copy";
    fs::remove_all(copy);
    fs::copy(dir_, copy, fs::copy_options::recursive);

    expect_series(copy, expected_, 8, VTK_QUAD, info_);
    EXPECT_TRUE(temporary_files(copy).empty());
    write_expectation(copy, VTK_QUAD, 8);
    expect_python_reads(copy);
}

TEST_F(VtkSeriesTest, BondsAsLinesAndUncompressed) {
    make_system();
    VtkSeries observer = make_observer(VtkSeries::Cells::bonds, false);
    observer.begin(view());
    observe(observer, 0);
    observe(observer, 1);
    observer.end(view());
    expect_series(dir_, expected_, 22, VTK_LINE, info_);
}

TEST_F(VtkSeriesTest, ABodyWithoutQuadsFallsBackToItsBonds) {
    make_system(false);
    VtkSeries observer = make_observer(VtkSeries::Cells::quads);
    observer.begin(view());
    observe(observer, 0);
    observer.end(view());
    expect_series(dir_, expected_, 22, VTK_LINE, info_);
}

TEST_F(VtkSeriesTest, TheSameStateIsWrittenOnce) {
    make_system();
    VtkSeries observer = make_observer();
    observer.begin(view());
    observe(observer, 0);
    observer.observe(view());  // the run observes again at a stage end and at the end
    observer.end(view());
    EXPECT_EQ(read_collection(dir_ / "lattice.pvd").size(), 1u);
    EXPECT_FALSE(fs::exists(dir_ / "lattice" / "lattice_000001.vtu"));
}

TEST_F(VtkSeriesTest, AFieldNamedLikeAComputedArrayIsRefused) {
    make_system();
    quantities_.field("displacement", "interface", nx, "m", "clashes with the observer's own array");
    VtkSeries observer = make_observer();
    EXPECT_THROW(observer.begin(view()), RunError);
}

TEST_F(VtkSeriesTest, EndWithoutBeginWritesNothing) {
    make_system();
    VtkSeries observer = make_observer();
    observer.end(view());  // a run that failed before its first stage
    EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(VtkSeriesTest, TheFileHoldsTheTimeTheCollectionLists) {
    make_system();
    info_.loading_start = 0.01;  // a settle of 10 ms
    VtkSeries observer = make_observer();
    observer.begin(view());
    // 1.25 million steps of 2e-7 s summed one by one land a few 1e-12 s off 0.25.
    double t = 0;
    for (int i = 0; i < 1'250'000; ++i) t += 2e-7;
    ASSERT_NE(t, 0.25);
    system_->accept(t, system_->y());
    system_->refresh();
    observer.observe(view());
    observer.end(view());
    const auto entries = read_collection(dir_ / "lattice.pvd");
    ASSERT_EQ(entries.size(), 1u);
    EXPECT_EQ(entries[0].time, 0.25);
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName((dir_ / entries[0].file).c_str());
    reader->Update();
    for (const char* name : {"TIME", "TimeValue"}) {
        vtkDataArray* array = reader->GetOutput()->GetFieldData()->GetArray(name);
        ASSERT_NE(array, nullptr) << name;
        EXPECT_EQ(array->GetComponent(0, 0), 0.25) << name << ": as the .pvd lists it, not " << t;
    }
    // The time since loading started, rounded alike, beside the run's clock in both.
    vtkDataArray* since = reader->GetOutput()->GetFieldData()->GetArray("time_since_loading");
    ASSERT_NE(since, nullptr);
    EXPECT_EQ(since->GetComponent(0, 0), 0.24);
    EXPECT_NE(
        frictionlab::testing::read_text(dir_ / "lattice.pvd").find("timestep=\"0.25\" time_since_loading=\"0.24\""),
        std::string::npos)
        << frictionlab::testing::read_text(dir_ / "lattice.pvd");
}

TEST(VtkSeriesCollection, TimesAreWrittenWithoutTheDriftOfASumOfSteps) {
    // 2.04 million steps of 2e-7 s summed one by one land 1e-11 s off 0.408.
    double t = 0;
    for (int i = 0; i < 2'040'000; ++i) t += 2e-7;
    ASSERT_NE(t, 0.408);
    EXPECT_EQ(VtuCollection::collection_time(t, 2'040'000), "0.408");
    EXPECT_EQ(VtuCollection::collection_time(0.25, 1), "0.25");
    EXPECT_EQ(VtuCollection::collection_time(0, 0), "0");
    // A time between two observations on the step grid keeps its digits: 3 steps of 1e-7 s.
    EXPECT_EQ(VtuCollection::collection_time(3e-7, 3), "0.0000003");
    EXPECT_EQ(VtuCollection::collection_time(1.23456789e-3, 1000), "0.00123457");  // a hundredth of 1.2e-6 s
    // Another clock of the same snapshot keeps the run clock's decimals, and its sign while settling.
    EXPECT_EQ(VtuCollection::collection_time(t - 0.01, t, 2'040'000), "0.398");
    EXPECT_EQ(VtuCollection::collection_time(0.002 - 0.01, 0.002, 10'000), "-0.008");
    EXPECT_EQ(VtuCollection::collection_time(-1e-12, 0.01, 50'000), "0") << "loading's start itself";
}

TEST(VtkSeriesSpec, PrefixMustBeAPlainFileName) {
    const auto rules = VtkSeries::spec().erased_rules();
    ASSERT_EQ(rules.size(), 2u);  // its characters, then the names it makes
    EXPECT_EQ(rules[0].check({{"prefix", std::string("lattice")}}), "");
    EXPECT_NE(rules[0].check({{"prefix", std::string("out/lattice")}}), "");
    EXPECT_NE(rules[0].check({{"prefix", std::string("")}}), "");
    EXPECT_EQ(rules[1].key, "prefix");
    EXPECT_EQ(rules[1].check({{"prefix", std::string("lattice")}}), "");
    // The folder would be the output directory's parent; checkpoint.pvd is a name of the run's own.
    EXPECT_EQ(rules[1].check({{"prefix", std::string("..")}}), "must name a file, not '..'");
    EXPECT_NE(rules[1].check({{"prefix", std::string("checkpoint")}}).find("'checkpoint.pvd' is a name of the run's"),
              std::string::npos);
}

TEST(VtkSeriesSpec, DeclaresItsFoldersAndCollections) {
    // The interface's series too, which a 3D body's run writes: no other output may take its names.
    const auto outputs = VtkSeries::spec().erased_outputs()({{"prefix", std::string("lattice")}});
    ASSERT_EQ(outputs.size(), 4u);
    EXPECT_EQ(outputs[0].name, "lattice");
    EXPECT_EQ(outputs[1].name, "lattice.pvd");
    EXPECT_EQ(outputs[2].name, "lattice_interface");
    EXPECT_EQ(outputs[3].name, "lattice_interface.pvd");
    for (const auto& o : outputs) EXPECT_EQ(o.key, "prefix");
}

TEST(VtkSeriesSpec, ItsDescriptionNamesTheCellArraysWithTheirUnit) {
    // What `frictionlab doc observer/vtk_series` prints first.
    const std::string summary = VtkSeries::spec().summary();
    for (const char* name : {"strain_xx", "strain_zz", "strain_xz", "stress_xx", "stress_zz", "stress_xz", "Pa"})
        EXPECT_NE(summary.find(name), std::string::npos) << name << " in: " << summary;
}

TEST(VtkSeriesPlugin, TheLibraryLoadsAndRegistersTheObserver) {
    Registry registry;
    const PluginRecord record = registry.load(fs::path(FRICTIONLAB_PLUGIN_DIR) / "observer_vtk_series.so");
    EXPECT_EQ(record.name, "observer_vtk_series");
    const TypeInfo* type = registry.find(Kind::observer, "vtk_series");
    ASSERT_NE(type, nullptr);
    std::vector<std::string> keys;
    for (const auto& p : type->params) keys.push_back(p.key);
    EXPECT_EQ(keys, (std::vector<std::string>{"prefix", "cells", "compress", "points"}));
}

}  // namespace
}  // namespace frictionlab
