#pragma once
// A series of .vtu snapshots of one grid and the .pvd collection that lists them with their times.
#include <filesystem>
#include <string>

#include <vtkSmartPointer.h>

class vtkUnstructuredGrid;
class vtkXMLUnstructuredGridWriter;

namespace frictionlab {

/// In an output directory:
///
///     <prefix>.pvd                          the collection; open this one
///     <prefix>/<prefix>_000000.vtu, ...     one file per snapshot, numbered from 0
///
/// Every file is written under a temporary name and renamed, and the .pvd is rewritten after each
/// snapshot, so a run that stops anywhere leaves a series that opens. The .vtu files are binary
/// appended, ZLib-compressed or not. The .pvd lists each snapshot at its simulated time rounded to a
/// hundredth of the mean step so far, with its time since loading started as an attribute.
class VtuCollection {
public:
    VtuCollection(std::string prefix, bool compress);
    ~VtuCollection();
    VtuCollection(VtuCollection&&) noexcept;
    VtuCollection& operator=(VtuCollection&&) noexcept;

    /// What changes as it writes (checkpoints).
    template <class Archive>
    void serialize(Archive& ar) {
        ar(datasets_, snapshots_);
    }

    const std::string& prefix() const { return prefix_; }
    std::filesystem::path collection_file(const std::filesystem::path& output_directory) const;
    /// Writes `grid` as the next snapshot, at simulated time t after `steps` steps, and the collection.
    void write(vtkUnstructuredGrid& grid, const std::filesystem::path& output_directory, double t, long long steps,
               double loading_start);
    /// The collection as it stands (a resumed run's, cut back to its checkpoint).
    void write_collection(const std::filesystem::path& output_directory) const;
    int snapshots() const { return snapshots_; }

    /// The time a snapshot is listed at: `t` after `steps` steps, rounded to a hundredth of the mean
    /// step t/steps, as the shortest text (the sum of many steps drifts in the last digits).
    static std::string collection_time(double t, long long steps) { return collection_time(t, t, steps); }
    /// Another time of the snapshot (its time since loading started), rounded as `t` is.
    static std::string collection_time(double value, double t, long long steps);

private:
    std::string prefix_;
    vtkSmartPointer<vtkXMLUnstructuredGridWriter> writer_;
    std::string datasets_;  // the collection's <DataSet> lines so far
    int snapshots_ = 0;
};

}  // namespace frictionlab
