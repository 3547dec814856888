#pragma once
// A 3D body's interface as a surface of its own, so ParaView shows fronts on it directly.
#include <vector>

#include <vtkSmartPointer.h>

#include "frictionlab/model/body.hpp"
#include "frictionlab/model/quantities.hpp"
#include "frictionlab/model/state.hpp"

class vtkDoubleArray;
class vtkFieldData;
class vtkUnstructuredGrid;

namespace frictionlab {

/// The faces of the body's volumes whose four corners are all interface nodes, as quads over the
/// interface nodes (one point each, at its reference position or, `deformed`, where it is). Point data,
/// SI units, vectors in the body's axes: displacement (3, m), velocity (3, m/s), slip_speed (1, m/s:
/// the speed in the interface plane) and every field published over the interface (normal_force,
/// friction_force, slipping, the junction counts, ...). Field data: shared with the lattice's grid (its
/// times, scalars and provenance), so both files of a snapshot say the same.
class InterfaceSurface {
public:
    /// Empty (faces() == 0) for a body without volumes or without an interface set.
    InterfaceSurface(const Body& body, const Quantities& quantities, vtkFieldData* field_data, bool deformed);
    ~InterfaceSurface();

    Index faces() const;
    /// The grid at this state: points (if deformed), displacement, velocity and the fields.
    vtkUnstructuredGrid& update(const StageView& s, const Body& body);

private:
    struct Field {
        const Eigen::ArrayXd* values;
        vtkDoubleArray* array;
    };
    NodeSet nodes_;  // the interface, in set order: point k is nodes_[k]
    bool deformed_ = false;
    vtkSmartPointer<vtkUnstructuredGrid> grid_;
    vtkDoubleArray *points_ = nullptr, *displacement_ = nullptr, *velocity_ = nullptr, *slip_speed_ = nullptr;
    std::vector<Field> fields_;
    std::vector<int> tangential_;  // the interface plane's axes
};

}  // namespace frictionlab
