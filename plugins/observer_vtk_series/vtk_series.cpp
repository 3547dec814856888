#include "vtk_series.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <utility>

#include <fmt/format.h>
#include <vtkCellType.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>
#include <vtkTypeInt64Array.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "frictionlab/output/atomic_file.hpp"
#include "frictionlab/output/output_file_name.hpp"
#include "frictionlab/output/provenance.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/model/junction_counts.hpp"
#include "frictionlab/simulation/system.hpp"
#include "vtk_arrays.hpp"

namespace frictionlab {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// The point arrays this observer computes; a published field of the same name would be ambiguous.
constexpr std::string_view own_arrays[] = {"displacement", "velocity", "net_force", "role"};

std::string prefix_problem(const VtkSeries::Params& p) {
    if (p.prefix.empty()) return "prefix must not be empty";
    // It becomes a folder, file names and an XML attribute of the .pvd.
    if (p.prefix.find_first_of("/\\<>&\"'") != std::string::npos)
        return "prefix must be a plain file name (no / \\ < > & or quotes)";
    return "";
}

// The folder of the .vtu files, then the collection; a 3D body's interface series beside them.
std::vector<OutputName> outputs(const VtkSeries::Params& p) {
    return {{"prefix", p.prefix},
            {"prefix", p.prefix + ".pvd"},
            {"prefix", p.prefix + "_interface"},
            {"prefix", p.prefix + "_interface.pvd"}};
}

using vtk_arrays::set_vectors;

template <class Array>
Array* add_array(vtkFieldData* data, const std::string& name, int components, vtkIdType tuples) {
    return vtk_arrays::add<Array>(data, name, components, tuples);
}

void add_strings(vtkFieldData* data, const std::string& name, const std::vector<std::string>& values) {
    auto* a = add_array<vtkStringArray>(data, name, 1, static_cast<vtkIdType>(values.size()));
    for (std::size_t i = 0; i < values.size(); ++i) a->SetValue(static_cast<vtkIdType>(i), values[i]);
}

// SetValue() leaves the array's modification time alone, and the writer would then put the cached
// range of an earlier snapshot in the file's header.
template <class Array, class T>
void set_single(Array* array, const T& value) {
    array->SetValue(0, value);
    array->Modified();
}

template <std::size_t N>
void insert_cells(vtkUnstructuredGrid& grid, int type, const std::vector<std::array<Index, N>>& cells) {
    grid.Allocate(static_cast<vtkIdType>(cells.size()));
    vtkIdType ids[N];
    for (const auto& c : cells) {
        std::copy(c.begin(), c.end(), ids);
        grid.InsertNextCell(type, static_cast<vtkIdType>(N), ids);
    }
}

}  // namespace

ParamSpec<VtkSeries::Params> VtkSeries::spec() {
    ParamSpec<Params> s(
        "Lattice snapshots for ParaView: a .vtu file per observation (nodes at their reference positions with "
        "displacement, velocity, net force, node-set roles and every published field; each quad cell's strain "
        "strain_xx, strain_zz, strain_xz and the stress its springs carry, stress_xx, stress_zz, stress_xz in Pa) "
        "and a .pvd collection with their simulated times, valid after every snapshot.");
    s.add("prefix", &Params::prefix,
          "Name of the collection <prefix>.pvd and of the folder <prefix>/ of its .vtu files, in the run's output "
          "directory.");
    s.choice("cells", &Params::cells, {{"quads", Cells::quads}, {"bonds", Cells::bonds}},
             "Draw the lattice as its quad cells or as its springs (line cells); a body without quads uses its "
             "springs.");
    s.add("compress", &Params::compress, "ZLib-compress the binary data of the .vtu files.");
    s.choice("points", &Params::points, {{"reference", Points::reference}, {"deformed", Points::deformed}},
             "Points at the reference positions, with `displacement` for ParaView's Warp By Vector, or at the "
             "deformed positions (then do not warp: the displacement would count twice).");
    s.rule("prefix", prefix_problem);
    add_outputs(s, outputs);
    s.dimensions({2, 3});
    return s;
}

VtkSeries::VtkSeries(const Params& p, const Context&)
    : params_(spec().checked(p)),
      lattice_(params_.prefix, params_.compress),
      interface_collection_(params_.prefix + "_interface", params_.compress) {}

VtkSeries::~VtkSeries() = default;

std::filesystem::path VtkSeries::collection_file(const std::filesystem::path& output_directory) const {
    return lattice_.collection_file(output_directory);
}

void VtkSeries::begin(const RunView& view) {
    const Body& body = view.body;
    grid_ = vtkSmartPointer<vtkUnstructuredGrid>::New();
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(body.size());
    grid_->SetPoints(points);
    points_ = vtkDoubleArray::SafeDownCast(points->GetData());
    build_cells(body);
    set_vectors(points_, body.reference_position);  // updated per snapshot only with `points: deformed`
    add_strain(body);

    displacement_ = add_point_array("displacement", 3, "m");
    velocity_ = add_point_array("velocity", 3, "m/s");
    net_force_ = add_point_array("net_force", 3, "N");
    add_role(body);
    add_fields(view);
    add_pinned_fraction();
    add_field_data(view);
    if (params_.cells == Cells::quads && !body.volumes.empty()) {
        interface_ = std::make_unique<InterfaceSurface>(body, view.quantities, grid_->GetFieldData(),
                                                        params_.points == Points::deformed);
        if (interface_->faces() == 0) interface_.reset();
    }

    std::filesystem::create_directories(view.output_directory / params_.prefix);
    view.log.info("vtk_series: {} ({} points, {} cells, {} point arrays)",
                  collection_file(view.output_directory).string(), grid_->GetNumberOfPoints(),
                  grid_->GetNumberOfCells(), grid_->GetPointData()->GetNumberOfArrays());
}

void VtkSeries::build_cells(const Body& body) {
    if (params_.cells == Cells::quads && !body.cells.empty()) return insert_cells(*grid_, VTK_QUAD, body.cells);
    if (params_.cells == Cells::quads && !body.volumes.empty())
        return insert_cells(*grid_, VTK_HEXAHEDRON, body.volumes);
    if (!body.bonds.empty()) return insert_cells(*grid_, VTK_LINE, body.bonds);
    // A lone block has neither: vertices keep it visible.
    std::vector<std::array<Index, 1>> vertices(static_cast<std::size_t>(body.size()));
    for (std::size_t i = 0; i < vertices.size(); ++i) vertices[i] = {static_cast<Index>(i)};
    insert_cells(*grid_, VTK_VERTEX, vertices);
}

void VtkSeries::add_strain(const Body& body) {
    if (params_.cells != Cells::quads || body.cells.empty()) return;
    // Bilinear quad, corners counter-clockwise: shape-function derivatives at the centre.
    constexpr double dxi[4] = {-0.25, 0.25, 0.25, -0.25}, deta[4] = {-0.25, -0.25, 0.25, 0.25};
    corner_gradients_.reserve(body.cells.size());
    for (const auto& c : body.cells) {
        double j11 = 0, j12 = 0, j21 = 0, j22 = 0;  // d(x, z)/d(xi, eta)
        for (int k = 0; k < 4; ++k) {
            j11 += dxi[k] * body.x0()(c[k]), j12 += dxi[k] * body.z0()(c[k]);
            j21 += deta[k] * body.x0()(c[k]), j22 += deta[k] * body.z0()(c[k]);
        }
        const double det = j11 * j22 - j12 * j21;
        std::array<std::array<double, 2>, 4> g{};
        for (int k = 0; k < 4; ++k)
            g[k] = {(j22 * dxi[k] - j12 * deta[k]) / det, (-j21 * dxi[k] + j11 * deta[k]) / det};  // d/dx, d/dz
        corner_gradients_.push_back(g);
        cell_volumes_.push_back(4 * std::abs(det) * body.width);  // exact for parallelograms (the lattice's squares)
    }
    const auto cells = static_cast<vtkIdType>(body.cells.size());
    strain_xx_ = add_array<vtkDoubleArray>(grid_->GetCellData(), "strain_xx", 1, cells);
    strain_zz_ = add_array<vtkDoubleArray>(grid_->GetCellData(), "strain_zz", 1, cells);
    strain_xz_ = add_array<vtkDoubleArray>(grid_->GetCellData(), "strain_xz", 1, cells);
    units_.insert(units_.end(), {"strain_xx: 1", "strain_zz: 1", "strain_xz: 1"});
    if (!(body.width > 0)) return;  // no thickness: no stress
    virial_.setZero(cells, 3);
    stress_xx_ = add_array<vtkDoubleArray>(grid_->GetCellData(), "stress_xx", 1, cells);
    stress_zz_ = add_array<vtkDoubleArray>(grid_->GetCellData(), "stress_zz", 1, cells);
    stress_xz_ = add_array<vtkDoubleArray>(grid_->GetCellData(), "stress_xz", 1, cells);
    units_.insert(units_.end(), {"stress_xx: Pa", "stress_zz: Pa", "stress_xz: Pa"});
}

void VtkSeries::update_stress(const RunView& view) {
    if (!stress_xx_) return;
    virial_.setZero();
    view.system.for_each_effect([&](const Effect& e) { e.add_cell_virial(view.state, virial_); });
    for (Index c = 0; c < virial_.rows(); ++c) {
        const double volume = cell_volumes_[static_cast<std::size_t>(c)];
        const auto i = static_cast<vtkIdType>(c);
        stress_xx_->SetValue(i, virial_(c, 0) / volume);
        stress_zz_->SetValue(i, virial_(c, 1) / volume);
        stress_xz_->SetValue(i, virial_(c, 2) / volume);
    }
    for (auto* a : {stress_xx_, stress_zz_, stress_xz_}) a->Modified();
}

void VtkSeries::update_strain(const StageView& s, const Body& body) {
    for (std::size_t c = 0; c < corner_gradients_.size(); ++c) {
        double ux = 0, uz = 0, wx = 0, wz = 0;
        for (int k = 0; k < 4; ++k) {
            const Index n = body.cells[c][k];
            const double u = s.x[n] - body.x0()(n), w = s.z[n] - body.z0()(n);
            ux += corner_gradients_[c][k][0] * u, uz += corner_gradients_[c][k][1] * u;
            wx += corner_gradients_[c][k][0] * w, wz += corner_gradients_[c][k][1] * w;
        }
        const auto i = static_cast<vtkIdType>(c);
        strain_xx_->SetValue(i, ux);
        strain_zz_->SetValue(i, wz);
        strain_xz_->SetValue(i, 0.5 * (uz + wx));
    }
    for (auto* a : {strain_xx_, strain_zz_, strain_xz_})
        if (a) a->Modified();
}

vtkDoubleArray* VtkSeries::add_point_array(const std::string& name, int components, const std::string& unit) {
    units_.push_back(name + ": " + (unit.empty() ? "-" : unit));
    return add_array<vtkDoubleArray>(grid_->GetPointData(), name, components, grid_->GetNumberOfPoints());
}

void VtkSeries::add_role(const Body& body) {
    units_.push_back("role: -");
    auto* role = add_array<vtkIntArray>(grid_->GetPointData(), "role", 1, grid_->GetNumberOfPoints());
    role->FillValue(0);
    const std::pair<const char*, int> bits[] = {{"top", Role::top},
                                                {"interface", Role::interface},
                                                {"trailing_edge", Role::trailing_edge},
                                                {"leading_edge", Role::leading_edge}};
    for (const auto& [set, bit] : bits) {
        const auto it = body.node_sets.find(set);
        if (it == body.node_sets.end()) continue;
        for (Index node : it->second) role->SetValue(node, role->GetValue(node) | bit);
    }
}

void VtkSeries::add_fields(const RunView& view) {
    for (const auto& [name, field] : view.quantities.fields()) {
        if (std::find(std::begin(own_arrays), std::end(own_arrays), name) != std::end(own_arrays))
            throw RunError(
                fmt::format("vtk_series: a published field is named '{}', like an array this observer "
                            "computes; rename the field",
                            name));
        const NodeSet& nodes = view.body.nodes(field.node_set);
        if (static_cast<Index>(nodes.size()) != field.values.size())
            throw RunError(fmt::format("vtk_series: field '{}' has {} values but its node set '{}' has {} nodes", name,
                                       field.values.size(), field.node_set, nodes.size()));
        vtkDoubleArray* array = add_point_array(name, 1, field.unit);
        array->FillValue(nan);  // off the node set, once: updates only touch the set's nodes
        fields_.push_back({&field.values, &nodes, array});
    }
}

void VtkSeries::add_pinned_fraction() {
    vtkPointData* data = grid_->GetPointData();
    const auto find = [&](std::string_view name) {
        return vtkDoubleArray::SafeDownCast(data->GetArray(std::string(name).c_str()));
    };
    junctions_ = {find(frictionlab::JunctionCounts::pinned_name), find(frictionlab::JunctionCounts::sliding_name),
                  find(frictionlab::JunctionCounts::dislocated_name), nullptr};
    // A friction law that publishes its own pinned_fraction is shown as published.
    if (junctions_.pinned && junctions_.sliding && junctions_.dislocated && !data->HasArray("pinned_fraction"))
        junctions_.fraction = add_point_array("pinned_fraction", 1, "1");
}

void VtkSeries::add_field_data(const RunView& view) {
    vtkFieldData* data = grid_->GetFieldData();
    when_.time = add_array<vtkDoubleArray>(data, "TIME", 1, 1);
    when_.time_value = add_array<vtkDoubleArray>(data, "TimeValue", 1, 1);
    when_.time_since_loading = add_array<vtkDoubleArray>(data, "time_since_loading", 1, 1);
    when_.step = add_array<vtkTypeInt64Array>(data, "STEP", 1, 1);
    when_.stage = add_array<vtkStringArray>(data, "stage", 1, 1);
    when_.stage_index = add_array<vtkIntArray>(data, "stage_index", 1, 1);
    for (const auto& [name, scalar] : view.quantities.scalars())
        scalars_.emplace_back(&scalar.value, add_array<vtkDoubleArray>(data, name, 1, 1));

    Provenance::of(view.info).visit(
        [&](const char* key, const std::string& value) { add_strings(data, key, {value}); },
        // A string: a double cannot hold every 64-bit seed.
        [&](const char* key, std::uint64_t value) { add_strings(data, key, {std::to_string(value)}); });
    add_strings(data, "units", units_);
}

void VtkSeries::observe(const RunView& view) {
    if (!grid_) throw RunError("vtk_series: observe() before begin()");
    if (view.step == last_step_) return;
    update(view);
    write_snapshot(view);
    last_step_ = view.step;
}

void VtkSeries::update(const RunView& view) {
    const StageView& s = view.state;
    const Body& body = view.body;
    if (params_.points == Points::deformed) {
        set_vectors(points_, s.position);
        grid_->GetPoints()->Modified();
    }
    update_strain(s, body);
    update_stress(view);
    set_vectors(displacement_, s.position - body.reference_position);
    set_vectors(velocity_, s.velocity);
    set_vectors(net_force_, view.system.net_force());
    for (const NodeField& field : fields_) {
        for (std::size_t k = 0; k < field.nodes->size(); ++k)
            field.array->SetValue((*field.nodes)[k], (*field.values)[static_cast<Index>(k)]);
        field.array->Modified();
    }
    update_pinned_fraction();
    for (const auto& [value, array] : scalars_) set_single(array, *value);
    // The times the .pvd lists, so that the series and a file opened alone agree to the digit.
    const auto listed = [](const std::string& text, double exact) {
        std::from_chars(text.data(), text.data() + text.size(), exact);
        return exact;
    };
    const double t = listed(VtuCollection::collection_time(s.t, view.step), s.t);
    set_single(when_.time, t);
    set_single(when_.time_value, t);
    const double since = s.t - view.info.loading_start;
    set_single(when_.time_since_loading, listed(VtuCollection::collection_time(since, s.t, view.step), since));
    set_single(when_.step, view.step);
    set_single(when_.stage, view.stage.name);
    set_single(when_.stage_index, view.stage.index);
}

void VtkSeries::update_pinned_fraction() {
    if (!junctions_.fraction) return;
    for (vtkIdType i = 0; i < junctions_.fraction->GetNumberOfTuples(); ++i) {
        const double pinned = junctions_.pinned->GetValue(i);
        const double total = pinned + junctions_.sliding->GetValue(i) + junctions_.dislocated->GetValue(i);
        // NaN off the interface propagates; a block without junctions has no fraction either.
        junctions_.fraction->SetValue(i, total > 0 ? pinned / total : nan);
    }
    junctions_.fraction->Modified();
}

void VtkSeries::write_snapshot(const RunView& view) {
    const double t = view.state.t;
    lattice_.write(*grid_, view.output_directory, t, view.step, view.info.loading_start);
    if (interface_)
        interface_collection_.write(interface_->update(view.state, view.body), view.output_directory, t, view.step,
                                    view.info.loading_start);
}

void VtkSeries::resumed(const RunView& view) {
    lattice_.write_collection(view.output_directory);
    if (interface_collection_.snapshots() > 0) interface_collection_.write_collection(view.output_directory);
}

void VtkSeries::end(const RunView& view) {
    if (!grid_) return;  // the run failed before it began observing
    view.log.info("vtk_series: {} snapshots in {}", lattice_.snapshots(),
                  collection_file(view.output_directory).string());
}

}  // namespace frictionlab
