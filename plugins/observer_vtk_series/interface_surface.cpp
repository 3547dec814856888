#include "interface_surface.hpp"

#include <array>
#include <cmath>
#include <map>

#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>

#include "vtk_arrays.hpp"

namespace frictionlab {

namespace {
// The faces of VTK_HEXAHEDRON by its corners: bottom, top, and the four sides.
constexpr std::array<std::array<int, 4>, 6> hexahedron_faces{
    {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};
}  // namespace

InterfaceSurface::InterfaceSurface(const Body& body, const Quantities& quantities, vtkFieldData* field_data,
                                   bool deformed)
    : deformed_(deformed), grid_(vtkSmartPointer<vtkUnstructuredGrid>::New()) {
    const auto set = body.node_sets.find("interface");
    if (body.volumes.empty() || set == body.node_sets.end()) return;
    nodes_ = set->second;
    tangential_ = body.contact_frame.tangential;
    std::map<Index, vtkIdType> point;
    for (std::size_t k = 0; k < nodes_.size(); ++k) point[nodes_[k]] = static_cast<vtkIdType>(k);
    for (const auto& volume : body.volumes)
        for (const auto& face : hexahedron_faces) {
            vtkIdType ids[4];
            bool on_interface = true;
            for (int c = 0; c < 4 && on_interface; ++c) {
                const auto found = point.find(volume[static_cast<std::size_t>(face[static_cast<std::size_t>(c)])]);
                on_interface = found != point.end();
                if (on_interface) ids[c] = found->second;
            }
            if (on_interface) grid_->InsertNextCell(VTK_QUAD, 4, ids);
        }
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(static_cast<vtkIdType>(nodes_.size()));
    grid_->SetPoints(points);
    points_ = vtkDoubleArray::SafeDownCast(points->GetData());
    vtk_arrays::set_vectors(points_, body.reference_position, &nodes_);
    const auto n = static_cast<vtkIdType>(nodes_.size());
    vtkPointData* data = grid_->GetPointData();
    displacement_ = vtk_arrays::add<vtkDoubleArray>(data, "displacement", 3, n);
    velocity_ = vtk_arrays::add<vtkDoubleArray>(data, "velocity", 3, n);
    slip_speed_ = vtk_arrays::add<vtkDoubleArray>(data, "slip_speed", 1, n);
    for (const auto& [name, field] : quantities.fields())
        if (field.node_set == "interface" && field.values.size() == n)
            fields_.push_back({&field.values, vtk_arrays::add<vtkDoubleArray>(data, name, 1, n)});
    grid_->SetFieldData(field_data);
}

InterfaceSurface::~InterfaceSurface() = default;

Index InterfaceSurface::faces() const { return grid_->GetNumberOfCells(); }

vtkUnstructuredGrid& InterfaceSurface::update(const StageView& s, const Body& body) {
    if (deformed_) {
        vtk_arrays::set_vectors(points_, s.position, &nodes_);
        grid_->GetPoints()->Modified();
    }
    vtk_arrays::set_vectors(displacement_, s.position - body.reference_position, &nodes_);
    vtk_arrays::set_vectors(velocity_, s.velocity, &nodes_);
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        double squared = 0;
        for (const int axis : tangential_) squared += s.velocity(nodes_[k], axis) * s.velocity(nodes_[k], axis);
        slip_speed_->SetValue(static_cast<vtkIdType>(k), std::sqrt(squared));
    }
    slip_speed_->Modified();
    for (const Field& f : fields_) {
        for (Index k = 0; k < f.values->size(); ++k) f.array->SetValue(static_cast<vtkIdType>(k), (*f.values)[k]);
        f.array->Modified();
    }
    return *grid_;
}

}  // namespace frictionlab
