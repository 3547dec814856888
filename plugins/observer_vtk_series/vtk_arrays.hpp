#pragma once
// Making and filling the VTK arrays of a snapshot.
#include <string>

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkSmartPointer.h>

#include "frictionlab/model/body.hpp"

namespace frictionlab::vtk_arrays {

/// A new array of `tuples` x `components` in `data`, which holds it; returned to fill in place.
template <class Array>
Array* add(vtkFieldData* data, const std::string& name, int components, vtkIdType tuples) {
    auto a = vtkSmartPointer<Array>::New();
    a->SetName(name.c_str());
    a->SetNumberOfComponents(components);
    a->SetNumberOfTuples(tuples);
    data->AddArray(a);
    return a;  // data holds a reference
}

/// A 3-vector per point from rows of an [n, ndim] array (row `rows[k]` for point k, or row k): a 3D
/// body's axes as VTK's, a planar body's x-z plane as VTK's x-y plane (0 out of it).
template <class Vectors>
void set_vectors(vtkDoubleArray* out, const Vectors& v, const NodeSet* rows = nullptr) {
    double* p = out->GetPointer(0);
    const Index n = rows ? static_cast<Index>(rows->size()) : v.rows();
    for (Index i = 0; i < n; ++i) {
        const Index r = rows ? (*rows)[static_cast<std::size_t>(i)] : i;
        for (Index k = 0; k < 3; ++k) p[3 * i + k] = k < v.cols() ? v(r, k) : 0;
    }
    out->Modified();
}

}  // namespace frictionlab::vtk_arrays
