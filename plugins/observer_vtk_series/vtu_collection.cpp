#include "vtu_collection.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkInformation.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "frictionlab/output/atomic_file.hpp"

namespace frictionlab {

VtuCollection::VtuCollection(std::string prefix, bool compress)
    : prefix_(std::move(prefix)), writer_(vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New()) {
    writer_->SetDataModeToAppended();
    writer_->EncodeAppendedDataOff();  // raw binary: smaller and faster than base64
    if (compress)
        writer_->SetCompressorTypeToZLib();
    else
        writer_->SetCompressorTypeToNone();
}

VtuCollection::~VtuCollection() = default;
VtuCollection::VtuCollection(VtuCollection&&) noexcept = default;
VtuCollection& VtuCollection::operator=(VtuCollection&&) noexcept = default;

std::filesystem::path VtuCollection::collection_file(const std::filesystem::path& output_directory) const {
    return output_directory / (prefix_ + ".pvd");
}

void VtuCollection::write(vtkUnstructuredGrid& grid, const std::filesystem::path& output_directory, double t,
                          long long steps, double loading_start) {
    // VTK caches the ranges it computed for an array in the array's information, and the writer
    // writes them: a snapshot would depend on what earlier ones computed (and a resumed run's on
    // where it resumed). Each snapshot is written from its values alone.
    for (vtkFieldData* data :
         {static_cast<vtkFieldData*>(grid.GetPointData()), static_cast<vtkFieldData*>(grid.GetCellData())})
        for (int a = 0; a < data->GetNumberOfArrays(); ++a)
            if (auto* array = data->GetAbstractArray(a); array && array->HasInformation())
                array->GetInformation()->Clear();
    if (auto* points = grid.GetPoints(); points && points->GetData()->HasInformation())
        points->GetData()->GetInformation()->Clear();
    std::filesystem::create_directories(output_directory / prefix_);
    const std::string name = fmt::format("{0}/{0}_{1:06d}.vtu", prefix_, snapshots_);
    writer_->SetInputData(&grid);
    replace_file_atomically(output_directory / name, [&](const std::filesystem::path& tmp) {
        writer_->SetFileName(tmp.c_str());
        return writer_->Write() == 1;
    });
    datasets_ +=
        fmt::format("    <DataSet timestep=\"{}\" time_since_loading=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n",
                    collection_time(t, steps), collection_time(t - loading_start, t, steps), name);
    ++snapshots_;
    write_collection(output_directory);
}

std::string VtuCollection::collection_time(double value, double t, long long steps) {
    if (steps <= 0 || t <= 0 || !std::isfinite(t) || !std::isfinite(value))
        return fmt::format("{}", value);  // shortest exact text
    // Decimals that resolve a hundredth of the mean step; the value rounded to them, trailing zeros cut.
    const int decimals =
        std::clamp(2 - static_cast<int>(std::floor(std::log10(t / static_cast<double>(steps)))), 0, 17);
    std::string text = fmt::format("{:.{}f}", value, decimals);
    if (text.find('.') != std::string::npos) {
        text.erase(text.find_last_not_of('0') + 1);
        if (text.back() == '.') text.pop_back();
    }
    return text == "-0" ? "0" : text;  // a time since loading that rounds to its start
}

void VtuCollection::write_collection(const std::filesystem::path& output_directory) const {
    write_file_atomically(collection_file(output_directory),
                          "<?xml version=\"1.0\"?>\n"
                          "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                          "  <Collection>\n" +
                              datasets_ + "  </Collection>\n</VTKFile>\n");
}

}  // namespace frictionlab
