#pragma once
// The binary archives a run's checkpoint is written to and read from (cereal's portable binary
// format: little-endian whatever the machine). A component saves what it keeps beyond its parameters
// and the state vector with one member template used in both directions:
//
//     template <class Archive> void serialize(Archive& ar) { ar(blocks_, next_event_); }
//     void save_state(StateOut& out) const override { out(*this); }
//     void restore_state(StateIn& in) override { in(*this); }
//
// Standard containers, strings, optionals, enums and Eigen's dense arrays and vectors go through as
// they are; a truncated or corrupted archive throws cereal::Exception.
#include <cereal/archives/portable_binary.hpp>
#include <cereal/types/array.hpp>
#include <cereal/types/optional.hpp>
#include <cereal/types/string.hpp>
#include <cereal/types/utility.hpp>
#include <cereal/types/vector.hpp>

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace frictionlab {

using StateOut = cereal::PortableBinaryOutputArchive;
using StateIn = cereal::PortableBinaryInputArchive;

/// The elements of a vector whose length the component's construction fixed (one per block, say),
/// archived in place: `ar(fixed_length(blocks_))` needs no default constructor, and a checkpoint
/// of another length does not read back.
template <class T>
struct FixedLength {
    std::vector<T>& items;

    template <class Archive>
    void save(Archive& ar) const {
        ar(static_cast<std::uint64_t>(items.size()));
        for (const T& item : items) ar(item);
    }
    template <class Archive>
    void load(Archive& ar) {
        std::uint64_t size = 0;
        ar(size);
        if (size != items.size())
            throw cereal::Exception("the checkpoint holds " + std::to_string(size) + " elements where this run has " +
                                    std::to_string(items.size()));
        for (T& item : items) ar(item);
    }
};

template <class T>
FixedLength<T> fixed_length(std::vector<T>& items) {
    return {items};
}

/// An optional member that the component's construction (or an observer's begin()) has engaged or
/// not, archived in place: `ar(as_built(detector_))` keeps what was built from the scene and reads
/// only its state.
template <class T>
struct AsBuilt {
    std::optional<T>& value;

    template <class Archive>
    void save(Archive& ar) const {
        ar(value.has_value());
        if (value) ar(*value);
    }
    template <class Archive>
    void load(Archive& ar) {
        bool engaged = false;
        ar(engaged);
        if (engaged != value.has_value())
            throw cereal::Exception("the checkpoint has a part of this component's state that this run does not");
        if (value) ar(*value);
    }
};

template <class T>
AsBuilt<T> as_built(std::optional<T>& value) {
    return {value};
}

}  // namespace frictionlab

namespace cereal {

/// Eigen's dense arrays and matrices: rows, columns, then the coefficients in storage order.
template <class Archive, class Dense>
requires std::is_base_of_v<Eigen::DenseBase<Dense>, Dense>
void save(Archive& ar, const Dense& m) {
    ar(static_cast<std::int64_t>(m.rows()), static_cast<std::int64_t>(m.cols()));
    ar(binary_data(m.data(), static_cast<std::size_t>(m.size()) * sizeof(typename Dense::Scalar)));
}

template <class Archive, class Dense>
requires std::is_base_of_v<Eigen::DenseBase<Dense>, Dense>
void load(Archive& ar, Dense& m) {
    std::int64_t rows = 0, cols = 0;
    ar(rows, cols);
    if (rows < 0 || cols < 0 || (Dense::RowsAtCompileTime != Eigen::Dynamic && rows != Dense::RowsAtCompileTime) ||
        (Dense::ColsAtCompileTime != Eigen::Dynamic && cols != Dense::ColsAtCompileTime) || rows * cols > (1LL << 40))
        throw Exception("an array of the checkpoint does not have the shape this run expects");
    m.resize(rows, cols);
    ar(binary_data(m.data(), static_cast<std::size_t>(m.size()) * sizeof(typename Dense::Scalar)));
}

}  // namespace cereal
