#pragma once
#include <array>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <vtkSmartPointer.h>

#include "frictionlab/base/state_archive.hpp"
#include "frictionlab/model/kinds.hpp"
#include "frictionlab/base/param_spec.hpp"
#include "frictionlab/simulation/run.hpp"
#include "interface_surface.hpp"
#include "vtu_collection.hpp"

class vtkDoubleArray;
class vtkIntArray;
class vtkStringArray;
class vtkTypeInt64Array;
class vtkUnstructuredGrid;

namespace frictionlab {

/// A time series of the lattice for ParaView: one VTK unstructured grid per observation and a
/// collection that lists them with their simulated times. In the run's output directory:
///
///     <prefix>.pvd                          the collection; open this one
///     <prefix>/<prefix>_000000.vtu, ...     one file per snapshot, numbered from 0
///
/// Every file is written under a temporary name and renamed, and the .pvd is rewritten after each
/// snapshot, so a run that stops anywhere (failure, kill) leaves a series that opens (vtu_collection.hpp).
/// The .vtu files are binary appended, ZLib-compressed unless `compress: false`. A state that was just
/// written (the run observes again at stage ends and at the end) is not written twice.
///
/// A 3D body's interface is besides a series of its own, <prefix>_interface.pvd and its folder, the
/// interface as a surface of quads with its blocks' displacement, velocity, slip_speed and the fields
/// published over it (interface_surface.hpp): open it in ParaView, colour by slip_speed and step
/// through the snapshots to watch a front cross the interface.
///
/// Geometry: one point per node at its reference position (x0, z0), written once, with the
/// `displacement` array for ParaView's Warp By Vector (scale 1: the deformed lattice; larger: the
/// deformation magnified); `points: deformed` writes the deformed positions instead, and then a warp
/// would count the displacement twice. A planar body's x-z plane is drawn as VTK's x-y, point =
/// (x, z, 0), so ParaView's default 2D view shows the slider upright, base at the bottom; a 3D body's
/// axes (x, y, z) are VTK's. Cells are the body's cells, quads in 2D (VTK_QUAD), hexahedra in 3D
/// (VTK_HEXAHEDRON), or, with `cells: bonds` or for a body without cells (a chain), its springs as
/// lines (VTK_LINE). Connectivity is built once in begin(); a snapshot updates array values.
///
/// Point data, SI units; vectors are laid out like the points, (x, z, 0) in 2D:
///
///     displacement     3   m     position - reference position
///     velocity         3   m/s
///     net_force        3   N     the sum of every effect's force at the observed state
///     role             1   -     bitmask of node sets: 1 top, 2 interface, 4 trailing edge, 8 leading edge
///     <field>          1   unit of the field: every field an effect publishes (glossary), e.g.
///                              normal_force, friction_force, junctions_pinned/sliding/dislocated
///     pinned_fraction  1   1     N_p / (N_p + N_s + N_d), when the three junction counts are published
///
/// A field is NaN on the nodes outside its node set, and pinned_fraction also on blocks without any
/// junction: an interior block has no normal force rather than a zero one, and ParaView's colour
/// ranges and filters skip NaN (it draws them in the NaN colour).
///
/// Cell data, 2D quads only (not yet for hexahedra): strain_xx, strain_zz, strain_xz (1), the small-strain tensor of
/// each cell from its corners' displacements (bilinear quad, displacement gradient at its centre; exact for a cell
/// deformed affinely), and stress_xx, stress_zz, stress_xz (Pa), the stress the bulk's springs carry through the cell
/// (their virial over its volume, Effect::add_cell_virial; the dashpots' viscous part is not included): what one looks
/// at around a rupture tip.
///
/// The .pvd lists each snapshot at its simulated time rounded to a hundredth of the mean step so far
/// (0.408, not the 0.40800000000967207 a sum of two million steps gives); TIME and TimeValue in the
/// file hold the same rounded time. That is the run's clock, from t = 0 with settling, as every plain
/// `time` is: ParaView's time axis then runs forward over the whole run in the order the snapshots
/// were taken, and a resumed run appends to it. The time since loading started, the figures'
/// clock, is beside it: each DataSet's `time_since_loading` attribute in the .pvd (ParaView's reader
/// passes over attributes it does not know) and the field array time_since_loading (negative while
/// settling), both rounded as the .pvd's time.
///
/// Field data: TIME (s), TimeValue (the same; VTK's readers take a file's time from this name when
/// the .vtu files are opened without the .pvd), time_since_loading (s), STEP, stage, stage_index, every published
/// scalar (e.g. driving_force in N), the run's provenance as every output records it (output/provenance.hpp: framework,
/// version, scene_file, scene_hash, seed, plugins) and units ("array: unit" for each point array).
///
/// In ParaView: File > Open <prefix>.pvd, Apply, colour by an array; the time controls step through
/// the snapshots at their simulated times. In Python: vtk.vtkXMLUnstructuredGridReader per file.
class VtkSeries final : public Observer {
public:
    // Checkpoints: what changes as it observes (its tables are cut back and appended to by the run).
    bool checkpointable() const override { return true; }
    void save_state(StateOut& out) const override { out(*this); }
    void restore_state(StateIn& in) override { in(*this); }
    template <class Archive>
    void serialize(Archive& ar) {
        ar(lattice_, interface_collection_, last_step_);
    }
    enum class Cells { quads, bonds };
    enum class Points { reference, deformed };
    struct Params {
        std::string prefix = "lattice";
        Cells cells = Cells::quads;
        bool compress = true;
        Points points = Points::reference;
    };
    static constexpr std::string_view type = "vtk_series";
    static ParamSpec<Params> spec();

    /// Bits of the "role" point array.
    struct Role {
        static constexpr int top = 1, interface = 2, trailing_edge = 4, leading_edge = 8;
    };

    VtkSeries(const Params& p, const Context&);
    ~VtkSeries() override;
    void begin(const RunView& view) override;
    void observe(const RunView& view) override;
    /// The collection as it was at the checkpoint (the run cut it back to its length then).
    void resumed(const RunView& view) override;
    void end(const RunView& view) override;

    /// The collection file, in the output directory.
    std::filesystem::path collection_file(const std::filesystem::path& output_directory) const;

private:
    /// A published field, drawn on the nodes of its set.
    struct NodeField {
        const Eigen::ArrayXd* values;
        const NodeSet* nodes;
        vtkDoubleArray* array;
    };
    struct JunctionCounts {
        vtkDoubleArray *pinned = nullptr, *sliding = nullptr, *dislocated = nullptr, *fraction = nullptr;
    };
    /// Field data that says when a snapshot is.
    struct When {
        vtkDoubleArray *time = nullptr, *time_value = nullptr, *time_since_loading = nullptr;
        vtkTypeInt64Array* step = nullptr;
        vtkStringArray* stage = nullptr;
        vtkIntArray* stage_index = nullptr;
    };

    void build_cells(const Body& body);
    void add_strain(const Body& body);
    void update_strain(const StageView& s, const Body& body);
    /// Each cell's stress: the effects' virial (Effect::add_cell_virial) over the cell's volume.
    void update_stress(const RunView& view);
    vtkDoubleArray* add_point_array(const std::string& name, int components, const std::string& unit);
    void add_role(const Body& body);
    void add_fields(const RunView& view);
    void add_pinned_fraction();
    void add_field_data(const RunView& view);
    void update(const RunView& view);
    void update_pinned_fraction();
    void write_snapshot(const RunView& view);

    Params params_;
    VtuCollection lattice_, interface_collection_;
    vtkSmartPointer<vtkUnstructuredGrid> grid_;
    std::unique_ptr<InterfaceSurface> interface_;  // a 3D body's; null without volumes
    // Owned by grid_; kept to update in place.
    vtkDoubleArray *points_ = nullptr, *displacement_ = nullptr, *velocity_ = nullptr, *net_force_ = nullptr;
    std::vector<NodeField> fields_;
    /// Per quad: d(u, w)/d(x, z) = sum_k gradient[k] (u_k, w_k) over its corners, from the reference
    /// geometry once; the strain arrays (none without quads).
    std::vector<std::array<std::array<double, 2>, 4>> corner_gradients_;
    vtkDoubleArray *strain_xx_ = nullptr, *strain_zz_ = nullptr, *strain_xz_ = nullptr;
    std::vector<double> cell_volumes_;  // m^3: reference area times the body's width
    Eigen::ArrayX3d virial_;            // scratch, per cell: xx, zz, xz (N m)
    vtkDoubleArray *stress_xx_ = nullptr, *stress_zz_ = nullptr, *stress_xz_ = nullptr;
    JunctionCounts junctions_;
    When when_;
    std::vector<std::pair<const double*, vtkDoubleArray*>> scalars_;
    std::vector<std::string> units_;
    long long last_step_ = -1;
};

}  // namespace frictionlab
